// The ghosts behind symmetry planes are the soil's mirror images (sph/stages/mirror_images.h): which
// soil particles get one, where it stands and what it carries, by hand; and the quarter column
// moves as the same quadrant of the whole one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "sph/collapse_3d.h"
#include "sph/stages/mirror_images.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
/// Soil particles at the given positions, each with velocity (1, 2, 3) m/s, mass 1 kg and density
/// 2000 kg/m³, and `ghosts` lattice ghosts after them (at the origin).
ParticlesOf<3> soil_at(const std::vector<sph::Vec3>& positions, std::size_t ghosts = 0) {
  ParticlesOf<3> p;
  p.resize(positions.size(), ghosts);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    p.x[i] = positions[i].x, p.y[i] = positions[i].y, p.z[i] = positions[i].z;
    p.vx[i] = 1.0, p.vy[i] = 2.0, p.vz[i] = 3.0;
    p.mass[i] = 1.0, p.density[i] = 2000.0;
  }
  return p;
}

/// The planes x = 0 (soil at x > 0, wall 1) and z = 0.01 (soil at z < 0.01, wall 2).
std::vector<SymmetryPlane> two_planes() {
  return {{.axis = 0, .offset = 0.0, .side = 1.0, .wall = 1}, {.axis = 2, .offset = 0.01, .side = -1.0, .wall = 2}};
}
}  // namespace

TEST_CASE("mirror images: one across each plane within reach, one across both within reach of their line",
          "[mirror-images]") {
  const double reach = 0.003;
  // a: 1 mm from x = 0 and 2 mm from z = 0.01, √5 mm < 3 mm from their line: three images;
  // b: 1 mm from x = 0, 2.5 mm from z = 0.01: two planes within reach, but √7.25 mm < 3 mm: three;
  // c: 2.5 mm from both: each within reach, the line √12.5 mm > 3 mm away: two images;
  // d: 4 mm from x = 0, 9 mm from z = 0.01: none.
  ParticlesOf<3> p = soil_at({{0.001, 0.05, 0.008}, {0.001, 0.0, 0.0075}, {0.0025, 0.02, 0.0075}, {0.004, 0.0, 0.001}}, 2);
  MirrorImagesOf<3> images(two_planes(), reach);
  images.rebuild(p, p.coordinates());
  REQUIRE(p.image_begin == 6);
  REQUIRE(p.image_count() == 8);
  REQUIRE(p.boundary_count() == 10);
  // In order of the soil particle, then of the set of planes: {x}, {z}, {x, z}.
  const std::vector<std::tuple<std::size_t, sph::Vec3>> expected = {
      {0, {-0.001, 0.05, 0.008}},  {0, {0.001, 0.05, 0.012}},  {0, {-0.001, 0.05, 0.012}},
      {1, {-0.001, 0.0, 0.0075}},  {1, {0.001, 0.0, 0.0125}},  {1, {-0.001, 0.0, 0.0125}},
      {2, {-0.0025, 0.02, 0.0075}}, {2, {0.0025, 0.02, 0.0125}}};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const auto& [source, at] = expected[k];
    const std::size_t b = p.image_begin + k;
    INFO("image " << k);
    CHECK(images.source(p, b) == source);
    CHECK(p.x[b] == Approx(at.x).margin(1e-15));
    CHECK(p.y[b] == Approx(at.y).margin(1e-15));
    CHECK(p.z[b] == Approx(at.z).margin(1e-15));
    // Reflected velocity, the soil's mass and density.
    const bool across_x = p.x[b] < 0.0, across_z = p.z[b] > 0.01;
    CHECK(p.vx[b] == (across_x ? -1.0 : 1.0));
    CHECK(p.vy[b] == 2.0);
    CHECK(p.vz[b] == (across_z ? -3.0 : 3.0));
    CHECK(p.mass[b] == 1.0);
    CHECK(p.density[b] == 2000.0);
    // Reported to the first of its planes, as a free-slip wall at rest.
    const std::size_t g = b - p.soil_count;
    CHECK(p.wall_id[g] == (across_x ? 1 : 2));
    CHECK(p.wall_friction[g] == 0.0);
  }
  // They follow their soil particles.
  p.x[0] = 0.0015, p.z[0] = 0.0085;
  images.place(p);
  CHECK(p.x[6] == Approx(-0.0015).margin(1e-15));
  CHECK(p.z[7] == Approx(0.0115).margin(1e-15));
  // Rebuilt from positions where a has left reach of both planes: the images of b and c remain.
  p.x[0] = 0.005, p.z[0] = 0.004;
  images.rebuild(p, p.coordinates());
  CHECK(p.image_count() == 5);
  CHECK(p.boundary_count() == 7);
}

TEST_CASE("a mirror image carries its soil particle's stress reflected: the shear across its plane changes sign",
          "[mirror-images]") {
  ParticlesOf<3> p = soil_at({{0.001, 0.0, 0.009}});
  p.sxx[0] = -1.0, p.syy[0] = -2.0, p.szz[0] = -3.0, p.sxy[0] = 0.4, p.sxz[0] = 0.5, p.syz[0] = 0.6;
  p.density[0] = 1900.0;
  MirrorImagesOf<3> images(two_planes(), 0.003);
  images.rebuild(p, p.coordinates());
  REQUIRE(p.image_count() == 3);
  for (std::size_t b = p.image_begin; b < p.size(); ++b) images.copy_stress(p, b);
  // σ'_ab = s_a s_b σ_ab: across x = 0, s = (−1, 1, 1); across z, (1, 1, −1); across both, (−1, 1, −1).
  const std::vector<std::array<double, 6>> expected = {{-1.0, -2.0, -3.0, -0.4, -0.5, 0.6},
                                                       {-1.0, -2.0, -3.0, 0.4, -0.5, -0.6},
                                                       {-1.0, -2.0, -3.0, -0.4, 0.5, -0.6}};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t b = p.image_begin + k;
    INFO("image " << k);
    CHECK(std::array<double, 6>{p.sxx[b], p.syy[b], p.szz[b], p.sxy[b], p.sxz[b], p.syz[b]} == expected[k]);
    CHECK(p.density[b] == 1900.0);
  }
}

TEST_CASE("the quarter column moves as the same quadrant of the whole one, to round-off", "[mirror-images]") {
  // The axisymmetric column at r0/Δp = 8, run 60 steps as a quarter (two symmetry planes) and whole.
  // The whole column's lattice and state are symmetric about both planes, so each quarter particle
  // must move as the whole column's particle that started where it did: the images stand where the
  // whole column's particles across the planes stand, and the floor's ghosts behind a plane average
  // them as the whole column's floor ghosts average its soil. Measured 2026-12-05: 1.4·10⁻¹⁷ m
  // against a largest displacement of 1.35 mm; with ghosts on a fixed lattice behind the planes
  // instead, 1.2·10⁻⁴ m (9 %), from the ghosts beside the column's top.
  const std::string column = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";
  const auto stepped = [&](const std::string& symmetry) {
    const std::vector<std::string> overrides = {"scene.particle_spacing=0.0125", "scene.symmetry=\"" + symmetry + "\""};
    const Scene3 scene = load_scene_3d(column, overrides);
    ParticlesOf<3> p = geostatic_particles(scene);
    const SolverSetupOf<3> setup = make_solver_setup(scene);
    WorkspaceOf<3> work(setup, p);
    const double dt = setup.initial_time_step();
    const auto& model = std::get<DruckerPrager>(scene.material);
    for (int step = 0; step < 60; ++step) advance(model, setup, p, work, dt);
    return p;
  };
  const ParticlesOf<3> quarter = stepped("quarter"), whole = stepped("none");
  REQUIRE(quarter.image_count() > 0);
  std::map<std::tuple<long long, long long, long long>, std::size_t> start;
  const auto key = [](double x, double y, double z) {
    return std::tuple{std::llround(x / 0.00125), std::llround(y / 0.00125), std::llround(z / 0.00125)};
  };
  for (std::size_t j = 0; j < whole.soil_count; ++j) start[key(whole.x0[j], whole.y0[j], whole.z0[j])] = j;
  double largest = 0.0, fastest = 0.0, largest_stress = 0.0;
  double worst_position = 0.0, worst_velocity = 0.0, worst_stress = 0.0;
  for (std::size_t i = 0; i < quarter.soil_count; ++i) {
    const std::size_t j = start.at(key(quarter.x0[i], quarter.y0[i], quarter.z0[i]));
    largest = std::max(largest, norm(quarter.position(i) - quarter.start_position(i)));
    fastest = std::max(fastest, norm(quarter.velocity(i)));
    worst_position = std::max(worst_position, norm(quarter.position(i) - whole.position(j)));
    worst_velocity = std::max(worst_velocity, norm(quarter.velocity(i) - whole.velocity(j)));
    const Mat3 difference = quarter.state[i].stress - whole.state[j].stress;
    largest_stress = std::max(largest_stress, quarter.state[i].stress.cwiseAbs().maxCoeff());
    worst_stress = std::max(worst_stress, difference.cwiseAbs().maxCoeff());
  }
  INFO("largest displacement " << largest << " m, speed " << fastest << " m/s, stress " << largest_stress
                               << " Pa; largest differences from the whole column: " << worst_position << " m, "
                               << worst_velocity << " m/s, " << worst_stress << " Pa");
  REQUIRE(largest > 1e-4);
  CHECK(worst_position < 1e-10 * largest);
  CHECK(worst_velocity < 1e-10 * fastest);
  CHECK(worst_stress < 1e-10 * largest_stress);
}
