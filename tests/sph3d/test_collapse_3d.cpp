// Collapses of space against the plane and against closed forms: the paper's column extruded
// between two free-slip planes rests as the 2D column does at the same spacing, and a confined
// slab at rest keeps the geostatic K0 stress; the tall axisymmetric column's foot keeps its density.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../common/pair_rows.h"
#include "sph/collapse.h"
#include "sph/collapse_3d.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
const std::string kSlab = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/slab-3d.toml";
const std::string kColumn2d = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/collapse-dp.toml";

/// How far a slab's deposit may lie from the plane's: the runouts and the height relative, the
/// repose angle in degrees.
struct DepositBands {
  double runout_thick;  ///< where the deposit is H0/10 thick
  double runout;        ///< the farthest toe particle
  double height;
  double angle_deg;
};

/// Runs the slab and the plane's column to rest on two threads and checks the slab's deposit within
/// `bands` of the plane's; returns the slab's run.
RunStatistics check_rests_as_plane(const Scene3& slab_scene, const Scene& plane_scene, DepositBands bands) {
  Collapse3 slab(slab_scene);
  Collapse plane(plane_scene);
  const RunStatistics slab_run = slab.run(ThreadTuner(2, false));
  const RunStatistics plane_run = plane.run(ThreadTuner(2, false));
  CHECK(slab_run.stopped_at_rest);
  CHECK(plane_run.stopped_at_rest);
  const DepositMetrics s = slab.slab_deposit(), p = plane.deposit();
  INFO("slab: runout " << s.runout_m << " m (" << s.runout_thick_m << " m where H0/10 thick), height "
                       << s.height_m << " m, angle " << s.repose_angle_deg << ", at rest at "
                       << slab_run.end_time << " s; plane: " << p.runout_m << " (" << p.runout_thick_m
                       << "), " << p.height_m << ", " << p.repose_angle_deg << ", " << plane_run.end_time
                       << " s");
  CHECK(s.runout_thick_m == Approx(p.runout_thick_m).epsilon(bands.runout_thick));
  CHECK(s.runout_m == Approx(p.runout_m).epsilon(bands.runout));
  CHECK(s.height_m == Approx(p.height_m).epsilon(bands.height));
  CHECK(s.repose_angle_deg == Approx(p.repose_angle_deg).margin(bands.angle_deg));
  return slab_run;
}

}  // namespace

TEST_CASE("the slab of space at 2 mm rests as the plane's column: runout within 3 %, height 2 %, angle 1 degree",
          "[collapse-3d]") {
  // 2 mm: 21 × 31 nodes in the plane, 5 layers through the slab's thickness.
  const std::vector<std::string> common = {"scene.particle_spacing=0.002", "scene.end_time=1.0",
                                           "output.frame_interval=1.0"};
  std::vector<std::string> slab_overrides = common;
  slab_overrides.push_back("scene.slab_thickness=0.01");
  const Scene3 slab_scene = load_scene_3d(kSlab, slab_overrides);
  const Scene plane_scene = load_scene(kColumn2d, common);
  REQUIRE(slab_scene.geometry.column_width == plane_scene.geometry.column_width);
  // Measured 2026-12-05 (the slab's planes mirrored by the soil's images): the runout where the
  // deposit is H0/10 thick 2.6 % short of the plane's (0.1085 m against 0.1113 m), the height 0.2 %,
  // the angle 0.3°; the farthest toe particle 14 % nearer (0.133 m against 0.155 m): the last
  // particles of a toe one or two particles thin are where the 3D and the 2D kernel sums differ most.
  // At the shipped 1 mm the body's runout is 1.1 % short (docs/validation/three-dimensions.md): the
  // gap closes with resolution; at this test's 2 mm, five layers through the slab, the band is 3 %.
  (void)check_rests_as_plane(slab_scene, plane_scene,
                             {.runout_thick = 0.03, .runout = 0.15, .height = 0.02, .angle_deg = 1.0});
}

TEST_CASE("the slab released by its lifted gate ([[boundaries]]) rests as the plane's gate-lift column",
          "[collapse-3d]") {
  // data/scenes/slab-gate-lift-3d.toml as shipped (2 mm, 5 layers, the gate a moving [[boundaries]]
  // rectangle) against data/scenes/gate-lift.toml at the same spacing. Measured 2026-12-05 (the
  // slab's planes mirrored by the soil's images): the runout where the deposit is H0/10 thick 1.7 %
  // shorter in the slab (0.1102 m against 0.1120 m), the farthest toe 8 % longer, the height 0.1 %
  // higher, the angle 0.1° steeper; both at rest at 0.44 s.
  const Scene3 slab_scene =
      load_scene_3d(std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/slab-gate-lift-3d.toml",
                    std::vector<std::string>{"output.frame_interval=1.0"});
  const Scene plane_scene =
      load_scene(std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/gate-lift.toml",
                 std::vector<std::string>{"scene.particle_spacing=0.002", "output.frame_interval=1.0"});
  REQUIRE(slab_scene.geometry.particle_spacing == plane_scene.geometry.particle_spacing);
  const RunStatistics slab_run = check_rests_as_plane(
      slab_scene, plane_scene, {.runout_thick = 0.02, .runout = 0.15, .height = 0.02, .angle_deg = 1.0});
  CHECK(slab_run.guard_corrections == 0);
}

TEST_CASE("a slab confined by its walls keeps the geostatic stress: sigma_yy = -rho g (H + dp/2 - y), K0 sideways",
          "[collapse-3d]") {
  // Elastic within the cone: K0 = ν/(1 − ν) is the stress an elastic soil takes under its own weight
  // in a confined column (ε_xx = ε_zz = 0), so nothing moves. With either kernel.
  const double nu = 0.3, k0 = nu / (1.0 - nu);
  const std::string kernel = GENERATE("cubic-spline", "wendland-c2");
  CAPTURE(kernel);
  const std::vector<std::string> overrides = {
      "scene.particle_spacing=0.004", "scene.end_time=0.05",      "scene.wall_withdrawal=\"none\"",
      "scene.stop_at_rest=false",     "scene.slab_thickness=0.016", "output.frame_interval=0.025",
      "initial.lateral_stress_ratio=" + std::to_string(k0), "numerics.kernel=\"" + kernel + "\""};
  const Scene3 scene = load_scene_3d(kSlab, overrides);
  Collapse3 collapse(scene);
  collapse.run(ThreadTuner(2, false));
  const ParticlesOf<3>& p = collapse.particles();
  const Geometry3& g = scene.geometry;
  const double rho = 2000.0, surface = g.column_height + 0.5 * g.particle_spacing;
  double worst_vertical = 0.0, worst_lateral = 0.0, fastest = 0.0;
  std::size_t interior = 0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    fastest = std::max(fastest, norm(p.velocity(i)));
    // Away from the walls and the free surface, where the SPH sums see a full neighbourhood.
    if (p.x0[i] < 0.01 || p.x0[i] > 0.03 || p.y0[i] < 0.01 || p.y0[i] > 0.045) continue;
    ++interior;
    const double sigma_v = -rho * 9.81 * (surface - p.y[i]);
    worst_vertical = std::max(worst_vertical, std::abs(p.syy[i] / sigma_v - 1.0));
    worst_lateral = std::max(worst_lateral, std::abs(p.szz[i] / (k0 * sigma_v) - 1.0));
  }
  INFO("interior particles " << interior << ", fastest " << fastest << " m/s");
  REQUIRE(interior > 100);
  CHECK(worst_vertical < 0.05);
  CHECK(worst_lateral < 0.10);
  CHECK(fastest < 5e-3);  // at rest: ρ g H / (ρ c) ≈ 0.05 m/s would be a free fall's first wave
}

TEST_CASE("the axisymmetric column at r0/dp = 10: runout radius near Lube et al.'s law, a quarter as a half",
          "[collapse-3d]") {
  const std::string column = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";
  const auto deposit_of = [&](const std::string& symmetry) {
    const std::vector<std::string> overrides = {"scene.particle_spacing=0.01", "scene.symmetry=\"" + symmetry + "\"",
                                                "output.frame_interval=0.5"};
    const Scene3 scene = load_scene_3d(column, overrides);
    Collapse3 collapse(scene);
    const RunStatistics run = collapse.run(ThreadTuner(2, false));
    CHECK(run.stopped_at_rest);
    return collapse.axisymmetric_deposit();
  };
  const AxisymmetricDeposit quarter = deposit_of("quarter"), half = deposit_of("half");
  const double r0 = 0.1, a = 1.0, lube = r0 * (1.0 + lube2004::runout_ratio(a));
  INFO("quarter: runout radius " << quarter.runout_radius_m << " m (spread " << quarter.runout_radius_spread_m
                                 << "), height " << quarter.height_m << " m; half: " << half.runout_radius_m
                                 << " m (spread " << half.runout_radius_spread_m << "), " << half.height_m
                                 << " m; Lube et al. 2004: " << lube << " m");
  // Lube et al.'s (r∞ − r0)/r0 = 1.24 a is a fit to sands, salt, rice and sugar; a D-P soil of
  // φ = 30° at ten particles per radius lands within 15 % of it.
  CHECK(quarter.runout_radius_m == Approx(lube).epsilon(0.15));
  // The symmetry planes: a quarter and a half of the same column spread alike (the half has one
  // plane and no corner of two).
  CHECK(quarter.runout_radius_m == Approx(half.runout_radius_m).epsilon(0.03));
  CHECK(quarter.height_m == Approx(half.height_m).epsilon(0.05));
  // The lattice's anisotropy: the runout varies over azimuths by less than a fifth of its mean.
  CHECK(quarter.runout_radius_spread_m < 0.2 * quarter.runout_radius_m);
}

// Eq 11 lets the density drift where the soil shears fast over the no-slip floor; the stress, which
// comes from eq 23, does not restore it (stages/continuity.h). The density diffusion (δ = 0.1) keeps
// the tall column's foot at its density; without it, as the scene runs, the same foot drifts to
// 1.62 ρ0 in some particles and 0.68 ρ0 in others by t = 0.2 s (2026-12-06).
TEST_CASE("the tall column's foot (a = 2, r0/dp = 10) keeps its density with the density diffusion",
          "[collapse-3d]") {
  const std::string column = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";
  const auto densities_after = [&](const std::string& diffusion) {
    const std::vector<std::string> overrides = {"scene.column_height=0.2", "scene.particle_spacing=0.01",
                                                "scene.end_time=0.2", "output.frame_interval=0.2",
                                                "numerics.density_diffusion=" + diffusion};
    const Scene3 scene = load_scene_3d(column, overrides);
    Collapse3 collapse(scene);
    collapse.run(ThreadTuner(2, false));
    const auto& p = collapse.particles();
    const auto [lo, hi] = std::minmax_element(p.density.begin(), p.density.begin() + p.soil_count);
    return std::pair(*lo / 2600.0, *hi / 2600.0);
  };
  const auto [lo, hi] = densities_after("0.1");
  INFO("densities " << lo << " to " << hi << " rho0");
  CHECK(lo > 0.85);
  CHECK(hi < 1.1);
  CHECK(densities_after("0").second > 1.15);
}

TEST_CASE("[numerics] kernel in space: a step's pair rows hold the Wendland C2 kernel, images and ghosts too",
          "[collapse-3d][kernel]") {
  // The quarter column at r0/Δp = 10: soil, ghosts under the floor and the soil's images behind the
  // two symmetry planes, whose ghost rows list them.
  const std::string column = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";
  const std::vector<std::string> overrides = {"scene.particle_spacing=0.01", "numerics.kernel=\"wendland-c2\""};
  const Scene3 scene = load_scene_3d(column, overrides);
  const Collapse3 collapse(scene);
  const SolverSetupOf<3>& setup = collapse.setup();
  REQUIRE(setup.kernel.shape() == KernelShape::WendlandC2);
  ParticlesOf<3> p = collapse.particles();
  WorkspaceOf<3> work(setup, p);
  // The first step searches and places the images; the second, within the skin, fills its rows
  // from the positions it starts at.
  const DruckerPrager& model = std::get<DruckerPrager>(scene.material);
  advance(model, setup, p, work, setup.initial_time_step());
  REQUIRE(p.image_begin < p.size());
  const ParticlesOf<3> at_start = p;
  const std::size_t searches = work.pairs.neighbours.searches();
  advance(model, setup, p, work, setup.initial_time_step());
  REQUIRE(work.pairs.neighbours.searches() == searches);
  const double h = setup.kernel.smoothing_length();
  CHECK(test::largest_row_difference(work.pairs.neighbours, at_start, WendlandC2Kernel<3>(h)) < 1e-12);
  CHECK(test::largest_row_difference(work.pairs.neighbours, at_start, CubicSplineKernel<3>(h)) > 0.1);
}
