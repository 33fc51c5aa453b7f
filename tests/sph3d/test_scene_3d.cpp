// 3D scenes (sph/scene_3d.h) and their initial particles and state (sph/initial_state_3d.h): the
// reader's defaults, refusals, overrides and resolved scene; the axisymmetric column's lattice
// against an independent count of the nodes in the quarter cylinder; the ghosts behind the walls;
// the geostatic K0 stress against its closed form.
#include <algorithm>
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "sph/initial_state.h"
#include "../common/material_toml.h"
#include "sph/blow_up.h"
#include "sph/initial_state_3d.h"
#include "sph/scene_3d.h"

using soilsph::Mat3;
using soilsph::ParameterError;
using namespace soilsph::sph;

namespace {

const std::string kColumn = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";
const std::string kSlab = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/slab-3d.toml";
const std::string kColumn2d = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/collapse-dp.toml";

/// A small axisymmetric column: r0 = H0 = 4 cm at 4 mm (r0/Δp = 10), without the shipped file.
const char* kSmallColumn = R"(
[scene]
dimension = 3
column_radius = 0.04
column_height = 0.04
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.5
[initial]
lateral_stress_ratio = 0.5
[material]
model = "drucker-prager"
density = 2600.0
young_modulus = 5.98e6
poisson_ratio = 0.3
friction_angle = 30.0
cohesion = 0.0
dilatancy_angle = 0.0
)";

/// Lattice nodes ((i + ½)Δp, (k + ½)Δp) with (i + ½)² + (k + ½)² ≤ (r0/Δp)², over i, k ≥ 0 (quarter),
/// k ≥ 0 (half) or all (none): counted directly, in units of Δp.
long long nodes_in_disc(int radius_in_spacings, int i_from, int k_from) {
  long long n = 0;
  const double r2 = static_cast<double>(radius_in_spacings) * radius_in_spacings;
  for (int i = i_from; i < radius_in_spacings + 1; ++i)
    for (int k = k_from; k < radius_in_spacings + 1; ++k)
      if ((i + 0.5) * (i + 0.5) + (k + 0.5) * (k + 0.5) <= r2) ++n;
  return n;
}

/// `what` throws a ParameterError whose message contains every one of `words`.
template <class F>
void require_refusal(F&& what, std::initializer_list<std::string> words) {
  try {
    what();
    FAIL("no error");
  } catch (const ParameterError& e) {
    const std::string message = e.what();
    INFO(message);
    for (const std::string& w : words) CHECK(message.find(w) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("the shipped axisymmetric column reads with its documented defaults", "[scene3d]") {
  const Scene3 s = load_scene_3d(kColumn);
  const Geometry3& g = s.geometry;
  CHECK(g.shape == Geometry3::Shape::AxisymmetricColumn);
  CHECK(g.column_radius == 0.1);
  CHECK(g.column_height == 0.1);
  CHECK(g.particle_spacing == 0.005);
  CHECK(g.symmetry == ColumnSymmetry::Quarter);
  CHECK(g.azimuth_span_deg == 90.0);
  // r0 (1 + 2 × 1.24 a) + 4 Δp with a = 1 (Lube et al. 2004).
  CHECK(g.floor_radius == Approx(0.1 * (1.0 + 2.0 * 1.24) + 4 * 0.005).epsilon(1e-12));
  CHECK(g.gravity == Vec3{0.0, -9.81, 0.0});
  CHECK(g.boundary_layers == 3);  // ⌈2 h/Δp⌉ = ⌈2.6⌉
  // The soil fills the cylinder r0 × H0 on the floor y = 0: the free surface at H0.
  CHECK(g.floor_level == 0.0);
  CHECK(g.surface_level == 0.1);
  CHECK(g.deposit_axis.point == Vec3{0.0, 0.0, 0.0});
  CHECK(g.deposit_axis.up == Vec3{0.0, 1.0, 0.0});
  REQUIRE(g.walls.size() == 3);
  CHECK(g.walls[0].label == "floor");
  CHECK(g.walls[0].kind == WallKind::NoSlip);
  CHECK(g.walls[1].kind == WallKind::FreeSlip);
  CHECK(g.walls[2].kind == WallKind::FreeSlip);
  CHECK(s.initial.lateral_stress_ratio == 0.5);
  CHECK(s.rest.enabled);
  CHECK(s.materials.size() == 1);
  // The domain holds the floor, its ghosts and the kernel support, and twice the soil's height.
  CHECK(g.domain.lo.x < -3 * 0.005);
  CHECK(g.domain.hi.x > g.floor_radius + 3 * 0.005);
  CHECK(g.domain.lo.y < g.floor_level - 3 * 0.005);
  CHECK(g.domain.hi.y >= g.floor_level + 2.0 * 0.1);
}

TEST_CASE("a 3D scene without gravity or symmetry keys takes (0, -9.81, 0) and the quarter", "[scene3d]") {
  const Scene3 s = parse_scene_3d(kSmallColumn, "small.toml");
  CHECK(s.geometry.gravity == Vec3{0.0, -9.81, 0.0});
  CHECK(s.geometry.symmetry == ColumnSymmetry::Quarter);
  const Scene3 g =
      parse_scene_3d(kSmallColumn, "small.toml", std::vector<std::string>{"scene.gravity=[0.0, -5.0, 0.0]"});
  CHECK(g.geometry.gravity == Vec3{0.0, -5.0, 0.0});
  const Scene3 scalar =
      parse_scene_3d(kSmallColumn, "small.toml", std::vector<std::string>{"scene.gravity=2.5"});
  CHECK(scalar.geometry.gravity == Vec3{0.0, -2.5, 0.0});
}

TEST_CASE("every refusal of a 3D scene names its key", "[scene3d]") {
  using Case = std::tuple<std::string, std::string>;  // override, the key the message names
  const Case cases[] = {
      {"scene.column_radius=-0.1", "column_radius"},
      {"scene.column_radius=0.042", "column_radius"},  // 10.5 spacings
      {"scene.column_height=0.041", "column_height"},  // 10.25 spacings
      {"scene.symmetry=\"eighth\"", "symmetry"},
      {"scene.floor_radius=0.03", "floor_radius"},  // inside the column
      {"scene.particle_spacing=0.02", "particle_spacing"},
      {"scene.gravity=[1.0, -9.81, 0.0]", "gravity"},  // not down y
      {"scene.gravity=[0.0, -9.81]", "gravity"},
      {"scene.dimension=4", "dimension"},
      {"scene.colum_radius=0.04", "colum_radius"},  // unknown key
      {"scene.column_width=0.04", "column_width"},  // both shorthands
      {"scene.boundary_layers=1", "boundary_layers"},
      {"initial.stress=\"gravity-relaxed\"", "stress"},
      {"initial.gravity_loading_damping=0.05", "gravity_loading_damping"},  // without "gravity-loading"
      {"initial.lateral_stress_ratio=0.1", "lateral_stress_ratio"},         // outside the D-P cone
      {"numerics.cfl=5.0", "cfl"},
      {"output.frame_interval=2.0", "frame_interval"},
      {"material.friction_angle=95.0", "friction_angle"},
  };
  for (const auto& [assignment, key] : cases) {
    SECTION(assignment) {
      require_refusal(
          [&] { (void)parse_scene_3d(kSmallColumn, "small.toml", std::vector<std::string>{assignment}); },
          {key});
    }
  }
  SECTION("a key refused in the file names the file") {
    std::string text = kSmallColumn;
    text.replace(text.find("column_radius = 0.04"), 20, "column_radius = 0.042");
    require_refusal([&] { (void)parse_scene_3d(text, "small.toml"); }, {"small.toml", "column_radius"});
  }
  SECTION("[[regions]] and a shorthand exclude each other; a shorthand takes no [deposit]") {
    require_refusal(
        [] { (void)parse_scene_3d(std::string(kSmallColumn) + "[[regions]]\nshape = \"box\"\n", "s.toml"); },
        {"s.toml", "regions"});
    require_refusal([] { (void)parse_scene_3d(std::string(kSmallColumn) + "[deposit]\n", "s.toml"); },
                    {"deposit"});
  }
}

TEST_CASE("the 2D and 3D readers each refuse the other's scene, and load_any_scene dispatches", "[scene3d]") {
  require_refusal([] { (void)load_scene(kColumn); }, {"dimension = 3", "load_scene_3d"});
  require_refusal([] { (void)load_scene_3d(kColumn2d); }, {"2D scene", "load_scene"});
  CHECK(std::holds_alternative<Scene3>(load_any_scene(kColumn)));
  CHECK(std::holds_alternative<Scene>(load_any_scene(kColumn2d)));
  // The dimension is read after the overrides: a 2D column made 3D lacks the slab's thickness.
  require_refusal([] { (void)load_any_scene(kColumn2d, std::vector<std::string>{"scene.dimension=3"}); },
                  {"slab_thickness", "--set scene.dimension=3"});
  const AnyScene slab =
      load_any_scene(kColumn2d, std::vector<std::string>{"scene.dimension=3", "scene.slab_thickness=0.005"});
  REQUIRE(std::holds_alternative<Scene3>(slab));
  CHECK(std::get<Scene3>(slab).overrides.size() == 2);
}

TEST_CASE("a 3D scene takes --set overrides, and its resolved scene reads back to the same scene",
          "[scene3d]") {
  const std::vector<std::string> set{"scene.column_height=0.2", "scene.symmetry=\"half\""};
  const Scene3 s = load_scene_3d(kColumn, set);
  CHECK(s.geometry.column_height == 0.2);
  CHECK(s.geometry.symmetry == ColumnSymmetry::Half);
  CHECK(s.geometry.azimuth_span_deg == 180.0);
  CHECK(s.overrides == set);
  // a = 2: (r∞ − r0)/r0 = 1.6 √2 beyond 1.7.
  CHECK(s.geometry.floor_radius == Approx(0.1 * (1.0 + 2.0 * 1.6 * std::sqrt(2.0)) + 0.02).epsilon(1e-12));
  const toml::table& scene = *s.resolved["scene"].as_table();
  for (const char* key :
       {"dimension", "column_radius", "column_height", "particle_spacing", "smoothing_ratio", "end_time",
        "gravity", "symmetry", "floor_radius", "boundary_layers", "stop_at_rest", "rest_speed",
        "rest_duration", "rest_fraction", "max_run_hours"})
    CHECK(scene.contains(key));
  for (const char* table : {"initial", "numerics", "output", "material"}) CHECK(s.resolved.contains(table));

  for (const std::string& file : {kColumn, kSlab}) {
    const Scene3 first = load_scene_3d(file, file == kColumn ? set : std::vector<std::string>{});
    const Scene3 again = parse_scene_3d(scene_toml(first), "scene.toml");
    CHECK(scene_toml(again) == scene_toml(first));
    CHECK(again.geometry.floor_radius == first.geometry.floor_radius);
    CHECK(again.geometry.floor_length == first.geometry.floor_length);
    CHECK(again.geometry.gravity == first.geometry.gravity);
    CHECK(again.geometry.walls.size() == first.geometry.walls.size());
    CHECK(again.initial.lateral_stress_ratio == first.initial.lateral_stress_ratio);
    CHECK(build_particles_3d(again).size() == build_particles_3d(first).size());
  }
}

TEST_CASE("the axisymmetric column holds the lattice nodes of its cylinder, each of mass rho dx^3",
          "[scene3d]") {
  // r0/Δp and H0/Δp: whole cells fill the cylinder on the floor y = 0, rows at (j + ½)Δp up to H0.
  const int radius = 10, rows = 10;
  const double dx = 0.004, rho = 2600.0;
  struct Expect {
    std::string symmetry;
    long long per_layer;
  };
  for (const Expect& e :
       {Expect{"quarter", nodes_in_disc(radius, 0, 0)}, Expect{"half", nodes_in_disc(radius, -radius - 1, 0)},
        Expect{"none", nodes_in_disc(radius, -radius - 1, -radius - 1)}}) {
    SECTION(e.symmetry) {
      const Scene3 s = parse_scene_3d(kSmallColumn, "small.toml",
                                      std::vector<std::string>{"scene.symmetry=\"" + e.symmetry + "\""});
      const ParticlesOf<3> p = build_particles_3d(s);
      const long long count = e.per_layer * rows;
      REQUIRE(static_cast<long long>(p.soil_count) == count);
      double mass = 0.0;
      for (std::size_t i = 0; i < p.soil_count; ++i) mass += p.mass[i];
      CHECK(mass == Approx(rho * static_cast<double>(count) * dx * dx * dx).epsilon(1e-12));
      for (std::size_t i = 0; i < p.soil_count; ++i) {
        CHECK(std::hypot(p.x[i], p.z[i]) <= 0.04 * (1 + 1e-9));
        CHECK(p.y[i] > 0.0);
        CHECK(p.y[i] < 0.04);
        CHECK(p.material[i] == 0);
        CHECK(p.x0[i] == p.x[i]);
        CHECK(p.z0[i] == p.z[i]);
      }
    }
  }
  // The counter itself against a count by hand: (k + ½)² ≤ 100 − (i + ½)² holds for 10, 10, 10, 9, 9,
  // 8, 8, 7, 5, 3 values of k at i = 0 … 9 (π r²/4 = 78.5).
  CHECK(nodes_in_disc(radius, 0, 0) == 79);
}

TEST_CASE("the column's ghosts lie behind their walls, never on a soil node, and cover the floor",
          "[scene3d]") {
  const Scene3 s = parse_scene_3d(kSmallColumn, "small.toml");
  const Geometry3& g = s.geometry;
  const ParticlesOf<3> p = build_particles_3d(s);
  const double dx = g.particle_spacing, depth = g.boundary_layers * dx;
  REQUIRE(p.boundary_count() > 0);
  const auto cell = [&](double x, double y, double z) {
    return std::tuple{std::llround(x / dx - 0.5), std::llround(y / dx - 0.5), std::llround(z / dx - 0.5)};
  };
  std::set<std::tuple<long long, long long, long long>> soil, ghosts;
  for (std::size_t i = 0; i < p.soil_count; ++i) soil.insert(cell(p.x[i], p.y[i], p.z[i]));
  for (std::size_t k = 0; k < p.boundary_count(); ++k) {
    const std::size_t i = p.soil_count + k;
    const auto at = cell(p.x[i], p.y[i], p.z[i]);
    CHECK(soil.count(at) == 0);
    CHECK(ghosts.insert(at).second);  // no two ghosts coincide
    const Wall3& wall = g.walls[static_cast<std::size_t>(p.wall_id[k])];
    const double behind = -wall.plane.height_above({p.x[i], p.y[i], p.z[i]});
    CHECK(behind > 0.0);
    CHECK(behind <= depth * (1 + 1e-9));
    CHECK(p.wall_nx[k] == wall.plane.inward.x);
    CHECK(p.wall_ny[k] == wall.plane.inward.y);
    CHECK(p.wall_nz[k] == wall.plane.inward.z);
    CHECK(p.wall_friction[k] ==
          (wall.kind == WallKind::NoSlip ? std::numeric_limits<double>::infinity() : 0.0));
    CHECK(p.density[i] == 2600.0);
  }
  // Under every soil node of the bottom row, boundary_layers ghosts, reaching on under the symmetry
  // planes; beside the planes none: the soil's mirror images stand there (stages/mirror_images.h).
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const auto [a, b, c] = cell(p.x[i], p.y[i], p.z[i]);
    if (b == 0)
      for (long long layer = 1; layer <= g.boundary_layers; ++layer) {
        CHECK(ghosts.count({a, -layer, c}) == 1);
        if (a == 0) CHECK(ghosts.count({-1, -layer, c}) == 1);
        if (c == 0) CHECK(ghosts.count({a, -layer, -1}) == 1);
      }
    if (a == 0) CHECK(ghosts.count({-1, b, c}) == 0);
    if (c == 0) CHECK(ghosts.count({a, b, -1}) == 0);
  }
}

TEST_CASE("the slab holds the 2D column's nodes in each of its layers between free-slip planes",
          "[scene3d]") {
  const Scene3 s = load_scene_3d(kSlab, std::vector<std::string>{"scene.particle_spacing=0.002"});
  const Geometry3& g = s.geometry;
  CHECK(g.shape == Geometry3::Shape::Slab);
  CHECK(g.wall_withdrawal == WallWithdrawal::Instant);
  CHECK(g.floor_length == 0.25);
  const ParticlesOf<3> p = build_particles_3d(s);
  CHECK(p.soil_count == 21u * 31u * 5u);  // (W/Δp + 1)(H/Δp + 1)(T/Δp)
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    CHECK(p.z[i] > 0.0);
    CHECK(p.z[i] < 0.01);
  }
  std::vector<std::string> labels;
  for (const Wall3& w : g.walls) labels.push_back(w.label);
  CHECK(labels == std::vector<std::string>{"floor", "fixed_wall", "symmetry_z", "symmetry_far"});
  const Scene3 kept = load_scene_3d(kSlab, std::vector<std::string>{"scene.wall_withdrawal=\"none\""});
  CHECK(kept.geometry.walls.size() == 5);
  require_refusal([] { (void)load_scene_3d(kSlab, std::vector<std::string>{"scene.slab_thickness=0.0105"}); },
                  {"slab_thickness"});
  require_refusal(
      [] { (void)load_scene_3d(kSlab, std::vector<std::string>{"scene.wall_withdrawal=\"lift\""}); },
      {"wall_withdrawal"});
  require_refusal([] { (void)load_scene_3d(kSlab, std::vector<std::string>{"scene.floor_length=0.01"}); },
                  {"floor_length"});
  require_refusal(
      [] { (void)load_scene_3d(kSlab, std::vector<std::string>{"scene.particle_spacing=0.003"}); },
      {"particle_spacing"});
}

TEST_CASE("the geostatic state of a 3D column is the K0 closed form below its top", "[scene3d]") {
  const Scene3 s = parse_scene_3d(kSmallColumn, "small.toml");
  ParticlesOf<3> p = build_particles_3d(s);
  set_geostatic_state_3d(p, s);
  const double rho = 2600.0, g = 9.81, k0 = 0.5, top = 0.04;  // H0: the cells fill the cylinder
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double vertical = -rho * g * (top - p.y[i]);
    const Mat3& sigma = p.state[i].stress;
    CHECK(sigma(1, 1) == Approx(vertical).epsilon(1e-13));
    CHECK(sigma(0, 0) == Approx(k0 * vertical).epsilon(1e-13));
    CHECK(sigma(2, 2) == Approx(k0 * vertical).epsilon(1e-13));
    CHECK(sigma(0, 1) == 0.0);
    CHECK(sigma(0, 2) == 0.0);
    CHECK(sigma(1, 2) == 0.0);
    CHECK(p.sxx[i] == sigma(0, 0));
    CHECK(p.syy[i] == sigma(1, 1));
    CHECK(p.szz[i] == sigma(2, 2));
    CHECK(p.sxy[i] == 0.0);
    CHECK(p.sxz[i] == 0.0);
    CHECK(p.syz[i] == 0.0);
  }
  // p at the lowest row, half a spacing above the floor: ρ g (H0 − Δp/2)(1 + 2 K0)/3.
  CHECK(largest_initial_pressure(s) ==
        Approx(rho * g * (top - 0.002) * (1.0 + 2.0 * k0) / 3.0).epsilon(1e-13));
}

TEST_CASE("a 3D column of Cam-clay starts on its yield surface's p_c, as in 2D", "[scene3d]") {
  std::string text = kSmallColumn;
  text = text.substr(0, text.find("[material]")) + soilsph::fixtures::kCamClayToml +
         "elasticity = \"constant\"\nyoung_modulus = 1.0e6\n";
  text.replace(text.find("lateral_stress_ratio = 0.5"), 26, "overconsolidation_ratio = 2");
  const Scene3 s = parse_scene_3d(text, "mcc.toml");
  ParticlesOf<3> p = build_particles_3d(s);
  set_geostatic_state_3d(p, s);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const Mat3& sigma = p.state[i].stress;
    const double mean = -sigma.trace() / 3.0;
    const Mat3 dev = sigma + mean * Mat3::Identity();
    const double q = std::sqrt(1.5 * (dev.array() * dev.array()).sum());
    // p_c = max(OCR (p + q²/(M² p)), floor) (eq 24 through the stress; initial_state.h), with
    // M = 6 sin φ / (3 − sin φ) (eq 26).
    const double sin_phi = std::sin(35.0 * 3.14159265358979323846 / 180.0),
                 M = 6.0 * sin_phi / (3.0 - sin_phi);
    const double yield = mean + q * q / (M * M * mean);
    CHECK(p.state[i].pc == Approx(std::max(2.0 * yield, 100.0)).epsilon(1e-10));
  }
}

TEST_CASE("the slab holds the 2D column's particles and geostatic stress in every layer", "[scene3d]") {
  // The 2D reader and builder (sph/scene.h, sph/initial_state.h) are the independent reference.
  const std::vector<std::string> coarse{"scene.particle_spacing=0.002"};
  const Scene plane = load_scene(kColumn2d, coarse);
  const Scene3 slab = load_scene_3d(kSlab, coarse);
  CHECK(slab.initial.lateral_stress_ratio == plane.initial.lateral_stress_ratio);
  CHECK(slab.rest.speed == plane.rest.speed);
  CHECK(slab.rest.duration == plane.rest.duration);
  CHECK(slab.numerics.cfl == plane.numerics.cfl);
  CHECK(slab.output.frame_interval == plane.output.frame_interval);
  CHECK(largest_initial_pressure(slab) == Approx(largest_initial_pressure(plane)).epsilon(1e-14));
  Particles p2 = build_particles(plane);
  set_geostatic_state(p2, plane);
  ParticlesOf<3> p3 = build_particles_3d(slab);
  set_geostatic_state_3d(p3, slab);
  const std::size_t layers = 5;  // T/Δp
  REQUIRE(p3.soil_count == layers * p2.soil_count);
  std::map<std::pair<long long, long long>, std::size_t> at;
  for (std::size_t i = 0; i < p2.soil_count; ++i)
    at[{std::llround(p2.x[i] / 0.002), std::llround(p2.y[i] / 0.002)}] = i;
  for (std::size_t i = 0; i < p3.soil_count; ++i) {
    const auto found = at.find({std::llround(p3.x[i] / 0.002), std::llround(p3.y[i] / 0.002)});
    REQUIRE(found != at.end());
    const std::size_t j = found->second;
    CHECK(p3.x[i] == Approx(p2.x[j]).margin(1e-15));
    CHECK(p3.y[i] == Approx(p2.y[j]).margin(1e-15));
    CHECK(p3.layer[i] == p2.layer[j]);
    CHECK(p3.mass[i] == Approx(p2.mass[j] * 0.002).epsilon(1e-14));  // ρΔp³ against ρΔp² per metre
    CHECK(p3.sxx[i] == Approx(p2.sxx[j]).epsilon(1e-13));
    CHECK(p3.syy[i] == Approx(p2.syy[j]).epsilon(1e-13));
    CHECK(p3.szz[i] == Approx(p2.state[j].stress(2, 2)).epsilon(1e-13));
  }
}

TEST_CASE("a 3D checkpoint's ghosts get their walls' normals, friction and ids from the scene", "[scene3d]") {
  const Scene3 s = parse_scene_3d(kSmallColumn, "small.toml");
  const ParticlesOf<3> built = build_particles_3d(s);
  ParticlesOf<3> restored;
  restored.resize(built.soil_count, built.boundary_count());
  copy_wall_attributes(restored, built);
  CHECK(restored.wall_nx == built.wall_nx);
  CHECK(restored.wall_ny == built.wall_ny);
  CHECK(restored.wall_nz == built.wall_nz);
  CHECK(restored.image_sign_x == built.image_sign_x);
  CHECK(restored.image_sign_y == built.image_sign_y);
  CHECK(restored.image_sign_z == built.image_sign_z);
  CHECK(restored.wall_friction == built.wall_friction);
  CHECK(restored.wall_id == built.wall_id);
  CHECK(restored.image_begin == built.size());
  ParticlesOf<3> fewer;
  fewer.resize(built.soil_count, built.boundary_count() - 1);
  CHECK_THROWS_AS(copy_wall_attributes(fewer, built), ParameterError);
  // A checkpoint holds the soil's mirror images after the ghosts: the scene's ghosts get their
  // walls' attributes, the images theirs when the run rebuilds them (solver.h).
  ParticlesOf<3> with_images;
  with_images.resize(built.soil_count, built.boundary_count() + 7);
  copy_wall_attributes(with_images, built);
  CHECK(with_images.image_begin == built.size());
  CHECK(with_images.image_count() == 7);
  CHECK(std::equal(built.wall_id.begin(), built.wall_id.end(), with_images.wall_id.begin()));
}

TEST_CASE("a soil particle off the floor's far end is named with the keys that lengthen each floor",
          "[scene3d][blow-up]") {
  ParticlesOf<3> p;
  p.resize(1, 0);
  p.x[0] = 0.6, p.y[0] = 0.05, p.z[0] = 0.05, p.density[0] = 2600.0;
  const Box3 domain{{-0.01, -0.01, -0.01}, {0.5, 0.4, 0.5}};
  REQUIRE(!particle_sane(p, 0, 0.0, 1.0, domain));
  const std::string message = particle_blow_up(p, 0, 1.0, domain);
  using Catch::Matchers::Contains;
  CHECK_THAT(message, Contains("left the domain") && Contains("floor_radius") && Contains("floor_length") &&
                          Contains("floor_margin"));
}
