// Whole runs at 2 mm: a column held by both walls stays at rest; the collapse runs to rest and its
// deposit lies within bands around the scaling laws; a vertical cut stands or fails as limit analysis
// bounds its critical height; SPHinXsys's low column keeps its height.
#include <catch2/catch.hpp>

#include "helpers.h"
#include "sph/analysis/deposit.h"
#include "sph/diagnostics.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
struct RunResult {
  Particles particles;
  RunStatistics stats;
  SolverSetup setup;
};

RunResult run_scene(const Scene& scene) {
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const SolverSetup setup = make_solver_setup(scene);
  const RunStatistics stats = std::visit(
      [&](const auto& model) {
        return run(
            model, setup, p, [](const Particles&, double) {}, [](double, std::size_t) {});
      },
      scene.material);
  return {std::move(p), stats, setup};
}

/// Both walls kept: after 0.2 s the column must still stand where it started.
void check_column_at_rest(const char* name, const std::string& kernel = "cubic-spline") {
  const Scene scene = test::shipped_scene(
      name, {"scene.particle_spacing=0.002", "scene.end_time=0.2", "scene.wall_withdrawal=\"none\"",
             "numerics.kernel=\"" + kernel + "\""});
  const RunResult r = run_scene(scene);
  REQUIRE(all_finite(r.particles));
  // "Tiny": below 0.1 % of the free-fall speed from the top of the column, √(2gH) = 1.08 m/s.
  CHECK(max_speed(r.particles) < 1e-3 * std::sqrt(2 * 9.81 * 0.06));
  CHECK(std::abs(top_of_soil(r.particles) - 0.06) < 0.01 * 0.06);
  CHECK(r.stats.guard_corrections == 0);
}

/// The wall withdrawn, at 2 mm: the run stays finite, the soil stays inside the walls and comes to
/// rest before the shipped end time (1 s), and the deposit lies within broad bands around the
/// scaling laws for a = H0/L0 = 1.5: L∞ between 0.8 × Lube et al. (11.2 cm) and
/// 1.2 × Lajeunesse et al. (14.8 cm), H∞ within 25 % of 4.7 cm, repose angle below φ = 35°.
void check_collapse(const char* name) {
  const Scene scene = test::shipped_scene(name, {"scene.particle_spacing=0.002"});
  REQUIRE(scene.geometry.end_time == 1.0);
  const RunResult r = run_scene(scene);
  REQUIRE(all_finite(r.particles));
  CHECK(r.stats.guard_corrections == 0);
  const Particles& p = r.particles;
  double xmin = 1.0, xmax = -1.0, ymin = 1.0;
  for (std::size_t i = 0; i < p.soil_count; ++i)
    xmin = std::min(xmin, p.x[i]), xmax = std::max(xmax, p.x[i]), ymin = std::min(ymin, p.y[i]);
  CHECK(xmax <= 0.04 + 0.5 * scene.geometry.particle_spacing);  // the fixed wall's surface
  CHECK(ymin >= -0.5 * scene.geometry.particle_spacing);        // the floor's surface
  CHECK(xmin > 0.04 - 0.25);  // still on the floor
  // At rest before the end time: 99 % of the particles below 1 % of √(2gH) for √(H/g) (sph/rest.h);
  // a few surface grains may still roll.
  CHECK(r.stats.stopped_at_rest);
  CHECK(r.stats.end_time < 1.0);
  std::size_t moving = 0;
  for (std::size_t i = 0; i < p.soil_count; ++i)
    moving += std::hypot(p.vx[i], p.vy[i]) > 0.01 * std::sqrt(2 * 9.81 * 0.06);
  CHECK(moving <= p.soil_count / 100);
  const DepositMetrics d =
      measure_deposit(std::span(p.x.data(), p.soil_count), std::span(p.y.data(), p.soil_count), 0.04, 0.002);
  CHECK(d.runout_m > 0.8 * 0.112);
  CHECK(d.runout_m < 1.2 * 0.148);
  CHECK(d.height_m == Approx(0.047).epsilon(0.25));
  CHECK(d.repose_angle_deg < 35.0);
}
}  // namespace

TEST_CASE("a D-P column held by both walls stays at rest for 0.2 s", "[column]") {
  check_column_at_rest("collapse-dp");
}
TEST_CASE("an MCC column held by both walls stays at rest for 0.2 s", "[column]") {
  check_column_at_rest("collapse-mcc");
}
TEST_CASE("a D-P column held by both walls stays at rest for 0.2 s with the Wendland C2 kernel",
          "[column][kernel]") {
  check_column_at_rest("collapse-dp", "wendland-c2");
}
TEST_CASE("the D-P collapse runs to rest at 2 mm within the scaling-law bands", "[column][collapse]") {
  check_collapse("collapse-dp");
}
TEST_CASE("the MCC collapse runs to rest at 2 mm within the scaling-law bands", "[column][collapse]") {
  check_collapse("collapse-mcc");
}

namespace {
/// The deposit of the MCC scene with a viscoplastic relaxation time, run to rest at `spacing`.
DepositMetrics viscous_mcc_deposit(double spacing) {
  const Scene scene = test::shipped_scene(
      "collapse-mcc", {"scene.particle_spacing=" + std::to_string(spacing), "scene.end_time=3",
                       "material.viscoplastic_relaxation_time=1.16e-4"});
  const RunResult r = run_scene(scene);
  REQUIRE(all_finite(r.particles));
  CHECK(r.stats.stopped_at_rest);
  CHECK(r.stats.guard_corrections == 0);
  const Particles& p = r.particles;
  return measure_deposit(std::span(p.x.data(), p.soil_count), std::span(p.y.data(), p.soil_count), 0.04, spacing,
                         0.1 * 0.06);
}
}  // namespace

// A softening soil with a material length has a deposit that does not depend on the particles once
// they resolve that length (the rate-independent MCC's does: its shear bands are as thin as the
// spacing; docs/validation/resolution.md). With G tau = 45 Pa s the paper's MCC column converges from 4 mm
// on (docs/validation/resolution.md): the runouts and the repose angle of the 4 and 2 mm
// runs within our goals (2 %, 1 deg); the height within 3 % (2.8 % measured: at 4 mm the
// column is 11 particles wide). Rate-independent, the same two runs differ by 2.6 deg in the angle
// and 4.9 % in the tip.
TEST_CASE("a viscous MCC column's deposit converges from 4 to 2 mm", "[column][collapse]") {
  const DepositMetrics coarse = viscous_mcc_deposit(0.004), fine = viscous_mcc_deposit(0.002);
  CHECK(coarse.runout_m == Approx(fine.runout_m).epsilon(0.02));
  CHECK(coarse.runout_thick_m == Approx(fine.runout_thick_m).epsilon(0.02));
  CHECK(coarse.height_m == Approx(fine.height_m).epsilon(0.03));
  CHECK(coarse.repose_angle_deg == Approx(fine.repose_angle_deg).margin(1.0));
}

namespace {
/// How far the cut's face moved: the fixed wall is at x = W, the face started at x = 0.
double face_displacement(const Particles& p) {
  double xmin = 1.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) xmin = std::min(xmin, p.x[i]);
  return -xmin;
}
}  // namespace

// An unsupported vertical cut in c-phi soil (data/scenes/vertical-cut.toml, c = 200 Pa, phi = 35°):
// limit analysis puts its critical height between 2 and 3.83 (c/gamma) tan(45° + phi/2), 3.92 and
// 7.50 cm. Well below the lower bound (3 cm, 2 mm spacing) it stands: the face moves less than one
// spacing in 0.2 s; well above the upper bound (8.8 cm, 4 mm spacing to keep the test short) it
// fails: the face moves more than five spacings within 0.2 s.
TEST_CASE("a vertical cut below the lower bound stands, one above the upper bound fails", "[column][cut]") {
  const RunResult low = run_scene(test::shipped_scene(
      "vertical-cut", {"scene.particle_spacing=0.002", "scene.end_time=0.2", "scene.stop_at_rest=false"}));
  REQUIRE(all_finite(low.particles));
  CHECK(face_displacement(low.particles) < 0.002);
  CHECK(top_of_soil(low.particles) > 0.03 - 0.002);

  const RunResult high = run_scene(test::shipped_scene("vertical-cut", {"scene.particle_spacing=0.004",
                                                                        "scene.column_height=0.088",
                                                                        "scene.end_time=0.2",
                                                                        "scene.stop_at_rest=false"}));
  REQUIRE(all_finite(high.particles));
  CHECK(face_displacement(high.particles) > 5.0 * 0.004);
}

TEST_CASE("SPHinXsys's column (aspect ratio 0.5) keeps its height and comes to rest on a slope below phi",
          "[column][sphinxsys]") {
  // data/scenes/sphinxsys-column-collapse.toml at 10 mm (21 × 11 particles; 2 mm in the file). A
  // column this low (a = H0/L0 = 0.5 < 1.15) collapses only at its front: the back keeps its height
  // (Lube et al. 2005; SPHinXsys's own result, H∞ ≈ H0), the front spreads beyond L0 and the deposit
  // rests before SPHinXsys's end time 0.8 s (its front is at rest from 0.52 s), sloping below φ = 21.9°.
  const Scene scene = test::shipped_scene("sphinxsys-column-collapse", {"scene.particle_spacing=0.01"});
  const RunResult r = run_scene(scene);
  REQUIRE(all_finite(r.particles));
  CHECK(r.stats.guard_corrections == 0);
  CHECK(r.stats.stopped_at_rest);
  CHECK(r.stats.end_time < 0.8);
  const Particles& p = r.particles;
  const DepositMetrics d =
      measure_deposit(std::span(p.x.data(), p.soil_count), std::span(p.y.data(), p.soil_count), 0.2, 0.01);
  CHECK(d.height_m == Approx(0.1).epsilon(0.01));
  CHECK(d.runout_m > 1.5 * 0.2);
  CHECK(d.repose_angle_deg < 21.9);
}
