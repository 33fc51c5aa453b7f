// Several materials in one scene: the soil grouped by material, each particle's own
// density in the geostatic state, and runs that the grouping does not change.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "helpers.h"
#include "sph/collapse.h"
#include "sph/diagnostics.h"
#include "../common/temp_dir.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
std::string shipped_text(const std::string& name) {
  std::ifstream in(SOILSPH_SOURCE_DIR "/data/scenes/" + name + ".toml");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with every occurrence of `from` replaced by `to` (at least one).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  for (; at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
  return text;
}

constexpr double kInterface = 0.032, kTop = 0.06, kWidth = 0.04;  // data/scenes/two-material-column.toml
const std::vector<std::string> kCoarse{"scene.particle_spacing=0.004"};
}  // namespace

TEST_CASE("the two-material column groups its soil by material, lower layer first", "[sph][materials]") {
  const Scene scene = test::shipped_scene("two-material-column", kCoarse);
  REQUIRE(scene.materials.size() == 2);
  CHECK(scene.material_names == std::vector<std::string>{"clay", "sand"});
  CHECK(model_name(scene.materials[0]) == "modified-cam-clay");
  CHECK(model_name(scene.materials[1]) == "drucker-prager");
  const Particles p = build_particles(scene);
  // Cells of 4 mm: 10 x 8 below the interface, 10 x 7 above it.
  REQUIRE(p.soil_count == 150);
  const MaterialGroups groups = material_groups(scene.materials, p);
  REQUIRE(groups.size() == 2);
  CHECK(groups[0].begin == 0);
  CHECK(groups[0].end == 80);
  CHECK(groups[1].begin == 80);
  CHECK(groups[1].end == 150);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    CHECK(p.material[i] == (p.y[i] < kInterface ? 0 : 1));
    CHECK(p.mass[i] == density(scene.materials[static_cast<std::size_t>(p.material[i])]) * 0.004 * 0.004);
  }
}

TEST_CASE("each layer's geostatic stress is the weight of the soil above it, each with its own density",
          "[sph][materials]") {
  // Lighter clay below the sand, so that a single density would be wrong in both layers' stresses.
  const double rho_clay = 1600.0, rho_sand = 2000.0, g = 9.81;
  const Scene scene = test::scene_from_text(
      replaced(shipped_text("two-material-column"), "model = \"modified-cam-clay\"\ndensity = 2000.0",
               "model = \"modified-cam-clay\"\ndensity = 1600.0"),
      kCoarse);
  REQUIRE(density(scene.materials[0]) == rho_clay);
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const double k0 = 0.3 / 0.7;  // both: nu/(1 - nu)
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double y = p.y[i];
    // The soil above y: sand from max(y, interface) to the top, clay from y to the interface.
    const double weight = rho_sand * (kTop - std::max(y, kInterface)) + rho_clay * std::max(kInterface - y, 0.0);
    const double sigma_v = -g * weight;
    CHECK(p.syy[i] == Approx(sigma_v).epsilon(1e-12));
    CHECK(p.sxx[i] == Approx(k0 * sigma_v).epsilon(1e-12));
    CHECK(p.sxy[i] == 0.0);
    CHECK(p.density[i] == (y < kInterface ? rho_clay : rho_sand));
  }
}

namespace {
struct Run {
  Particles particles;
  DepositMetrics deposit;
};

/// A scene run to its end (or rest) on `threads` threads.
Run run_to_end(const Scene& scene, int threads = 1) {
  Collapse collapse(scene);
  collapse.run(ThreadTuner(threads, false));
  return {collapse.particles(), collapse.deposit()};
}

/// Every field of the soil equal bit for bit.
void check_identical(const Run& a, const Run& b) {
  REQUIRE(a.particles.soil_count == b.particles.soil_count);
  for (std::vector<double> Particles::*field : {&Particles::x, &Particles::y, &Particles::vx, &Particles::vy, &Particles::sxx,
                            &Particles::syy, &Particles::sxy, &Particles::density})
    CHECK((a.particles.*field) == (b.particles.*field));
  for (std::size_t i = 0; i < a.particles.soil_count; ++i) {
    CHECK(a.particles.state[i].pc == b.particles.state[i].pc);
    CHECK(a.particles.state[i].stress(2, 2) == b.particles.state[i].stress(2, 2));  // σ_zz
  }
}

/// The two-material column with both regions of one material ("sand" or "clay").
std::string one_material_column(const std::string& name) {
  const std::string other = name == "sand" ? "clay" : "sand";
  return replaced(shipped_text("two-material-column"), "material = \"" + other + "\"", "material = \"" + name + "\"");
}
}  // namespace

TEST_CASE("two names for the same parameters run bit for bit as one material", "[sph][materials]") {
  // The clay layer made of sand's parameters under its own name: two groups of one model.
  const std::string text = shipped_text("two-material-column");
  const std::size_t clay = text.find("[materials.clay]"), sand = text.find("[materials.sand]"),
                    regions = text.find("\n\n[[regions]]");
  const std::size_t title = std::string("[materials.sand]").size();
  const std::string twice = text.substr(0, clay) + "[materials.clay]" + text.substr(sand + title, regions - sand - title) +
                            text.substr(sand - 2);
  const std::vector<std::string> shortly{"scene.particle_spacing=0.004", "scene.end_time=0.05"};
  const Scene two = test::scene_from_text(twice, shortly), one = test::scene_from_text(one_material_column("sand"), shortly);
  REQUIRE(two.materials.size() == 2);
  REQUIRE(one.materials.size() == 1);
  check_identical(run_to_end(two), run_to_end(one));
}

TEST_CASE("two threads run the two-material column bit for bit as one", "[sph][materials][threads]") {
  // Two threads share each soil loop in parts cut by measured cost (sph/range_balancer.h), which
  // move every step: a gap, an overlap or a race between the parts would show here. The clay's
  // plastic returns and the sand's make the costs of the two groups differ.
  const Scene scene = test::shipped_scene("two-material-column", {"scene.particle_spacing=0.004", "scene.end_time=0.1"});
  check_identical(run_to_end(scene, 2), run_to_end(scene, 1));
}

TEST_CASE("the two-material column keeps each material's particles and mass, and its deposit lies between "
          "those of its two soils",
          "[sph][materials]") {
  const std::vector<std::string> k2mm{"scene.particle_spacing=0.002"};
  const Scene scene = test::shipped_scene("two-material-column", k2mm);
  const Particles start = build_particles(scene);
  const Run two = run_to_end(scene);
  const Particles& p = two.particles;
  REQUIRE(all_finite(p));
  // Each particle keeps its material, and each material its mass: ρ × its cells' area (2 mm cells).
  CHECK(p.material == start.material);
  for (std::size_t k = 0; k < 2; ++k) {
    double mass = 0.0;
    for (std::size_t i = 0; i < p.soil_count; ++i) mass += p.material[i] == static_cast<int>(k) ? p.mass[i] : 0.0;
    const double area = kWidth * (k == 0 ? kInterface : kTop - kInterface);
    CHECK(mass == Approx(density(scene.materials[k]) * area).epsilon(1e-12));
  }
  // Replacing part of one soil by another cannot take the deposit beyond either soil's own: the
  // all-MCC column (its normally consolidated clay hardens as it shears) runs out least and stays
  // highest, the all-D-P one runs out furthest; half of each lies between them (measured at 2 mm:
  // 10.2, 11.1, 14.4 cm). At 4 mm (10 × 15 particles, a toe of one particle) the all-D-P runout
  // is within the toe's noise of the two-material one (10.9 and 11.4 cm with the ghosts' weight).
  const Run mcc = run_to_end(test::scene_from_text(one_material_column("clay"), k2mm));
  const Run dp = run_to_end(test::scene_from_text(one_material_column("sand"), k2mm));
  CHECK(mcc.deposit.runout_m < two.deposit.runout_m);
  CHECK(two.deposit.runout_m < dp.deposit.runout_m);
  CHECK(dp.deposit.height_m < two.deposit.height_m);
  CHECK(two.deposit.height_m < mcc.deposit.height_m);
}

TEST_CASE("each material integrates with its own scheme", "[sph][materials]") {
  const Scene scene = test::scene_from_text(
      replaced(shipped_text("two-material-column"), "integrator = \"implicit\"\n\n[materials.sand]",
               "integrator = \"explicit\"\n\n[materials.sand]"),
      {"scene.particle_spacing=0.004", "scene.end_time=0.05"});
  REQUIRE(std::get<ModifiedCamClay>(scene.materials[0]).integrator() == Integrator::Explicit);
  REQUIRE(std::get<DruckerPrager>(scene.materials[1]).integrator() == Integrator::Implicit);
  const Particles start = build_particles(scene);
  const MaterialGroups groups = material_groups(scene.materials, start);
  // The fallback of a failed update is substepping, each material its own (stages/stress_update.h).
  CHECK(std::get<ModifiedCamClay>(groups[0].fallback).integrator() == Integrator::Substep);
  CHECK(std::get<DruckerPrager>(groups[1].fallback).integrator() == Integrator::Substep);
  const Run run = run_to_end(scene);
  REQUIRE(all_finite(run.particles));
  // The column has started to spread (the wall is gone).
  CHECK(run.deposit.runout_m > kWidth);
}

namespace {
/// σ^{n+1} of soil particle i by `model` from its state before the step and the velocity gradient
/// of eq 23 recomputed from what the step left: v^{n+½} (now in p.vx, p.vy, ghosts mirrored), the
/// pairs (`at_start`: the particles at x^n, whose x_i − x_j the pairs take) and the volumes m/ρ^n;
/// nullopt where the model cannot update it.
template <class Model>
std::optional<Mat3> stress_by(const Model& model, const State& before, const Particles& at_start, const Particles& p,
                              const Workspace& work, const SolverSetup& setup, std::size_t i, double dt) {
  const VelocityGradient L = kinematic_rates_of(at_start, work.pairs.neighbours, i, {p.vx, p.vy},
                                                work.pairs.volume, setup.kinematics)
                                 .L;
  StepFailure ignored;
  try {
    return update_splitting_on_failure(model, fallback_model(model), before, L.strain_increment(dt),
                                       L.spin_increment(dt), ignored)
        .stress;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}
}  // namespace

TEST_CASE("each group's particles are updated by their own material's model, not the other's", "[sph][materials]") {
  // The two-material column 0.02 s after the wall's withdrawal (both soils yield at the toe), then one
  // more step: every particle's new stress must be its own model's update of its old state for the
  // step's strain increment, recomputed here. Both soils share E and nu, so the other model gives the
  // same elastic update; it differs where the soil yields, and enough particles yield in each layer
  // for a group run with the other group's model to fail this test.
  const Scene scene = test::shipped_scene("two-material-column", {"scene.particle_spacing=0.004"});
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const SolverSetup setup = make_solver_setup(scene);
  const MaterialGroups groups = material_groups(scene.materials, p);
  Workspace work(setup, p);
  work.balance.use_threads(1, groups.size());
  const double dt = setup.initial_time_step();
  for (double t = 0.0; t < 0.02; t += dt) advance_groups(groups, setup, p, work, dt, [] {});
  const std::vector<State> before(p.state.begin(), p.state.end());
  const Particles at_start = p;
  advance_groups(groups, setup, p, work, dt, [] {});
  REQUIRE_FALSE(work.health.failed());
  const auto& clay = std::get<ModifiedCamClay>(scene.materials[0]);
  const auto& sand = std::get<DruckerPrager>(scene.materials[1]);
  std::size_t told_apart[2] = {0, 0};
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const int k = p.material[i];
    const std::optional<Mat3> own = k == 0 ? stress_by(clay, before[i], at_start, p, work, setup, i, dt)
                                           : stress_by(sand, before[i], at_start, p, work, setup, i, dt);
    const std::optional<Mat3> other = k == 0 ? stress_by(sand, before[i], at_start, p, work, setup, i, dt)
                                             : stress_by(clay, before[i], at_start, p, work, setup, i, dt);
    INFO("particle " << i << " of material " << k);
    REQUIRE(own.has_value());
    const double scale = std::max(1.0, own->norm());
    CHECK((p.state[i].stress - *own).norm() <= 1e-9 * scale);
    if (!other || (p.state[i].stress - *other).norm() > 1e-6 * scale) ++told_apart[k];
  }
  INFO("particles where the other model's update differs: clay " << told_apart[0] << ", sand " << told_apart[1]);
  CHECK(told_apart[0] > 0);
  CHECK(told_apart[1] > 0);
}

TEST_CASE("particles imported from CSV reproduce the column's lattice", "[sph][import]") {
  const Scene imported = test::shipped_scene("imported-column", {"scene.end_time=0.02"});
  const Scene column = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004", "scene.end_time=0.02"});
  Collapse a(imported), b(column);
  const Particles &pa = a.particles(), &pb = b.particles();
  // The same soil: 11 x 16 positions bit for bit, in the same order, with the mass of the lattice.
  REQUIRE(pa.soil_count == 11 * 16);
  REQUIRE(pa.soil_count == pb.soil_count);
  CHECK(std::equal(pa.x.begin(), pa.x.begin() + 176, pb.x.begin()));
  CHECK(std::equal(pa.y.begin(), pa.y.begin() + 176, pb.y.begin()));
  CHECK(std::equal(pa.mass.begin(), pa.mass.begin() + 176, pb.mass.begin()));
  // The geostatic surface half a spacing above the highest particle, as the column's H + dp/2.
  CHECK(imported.geometry.surface_level == Approx(column.geometry.surface_level).margin(1e-15));
  for (std::size_t i = 0; i < pa.soil_count; ++i) CHECK(pa.syy[i] == Approx(pb.syy[i]).margin(1e-9));
  // The same walls (ghosts within round-off of the column's given rows), so the first steps agree.
  REQUIRE(pa.boundary_count() == pb.boundary_count());
  a.run(ThreadTuner(1, false));
  b.run(ThreadTuner(1, false));
  for (std::size_t i = 0; i < pa.soil_count; ++i) {
    CHECK(a.particles().x[i] == Approx(b.particles().x[i]).margin(1e-9));
    CHECK(a.particles().y[i] == Approx(b.particles().y[i]).margin(1e-9));
  }
}

TEST_CASE("a particle file is validated with the file and line named", "[sph][import]") {
  const soilsph::testing::TempDir scratch("soilsph-import-test");
  const std::string dir = scratch.path().string();
  const auto scene_with = [&](const std::string& csv) {
    std::ofstream(dir + "/p.csv") << csv;
    return test::scene_from_text(replaced(shipped_text("imported-column"), "file = \"imported-column.csv\"",
                                          "file = \"" + dir + "/p.csv\""));
  };
  using Catch::Matchers::Contains;
  CHECK(scene_with("x,y,region\n0.0,0.0,sand\n0.004,0.0,sand\n").materials.size() == 1);
  CHECK_THROWS_WITH(test::scene_from_text(replaced(shipped_text("imported-column"), "imported-column.csv", "/nonexistent/p.csv")),
                    Contains("/nonexistent/p.csv: cannot read"));
  CHECK_THROWS_WITH(scene_with("x,y\n0,0\n"), Contains("p.csv:1: the header must be x,y,region"));
  CHECK_THROWS_WITH(scene_with("x,y,region\n0.0,0.0,sand\n0.004,zero,sand\n"),
                    Contains("p.csv:3: y = \"zero\" is not a number"));
  CHECK_THROWS_WITH(scene_with("x,y,region\n0.0,0.0\n"), Contains("p.csv:2: expected 3 fields"));
  CHECK_THROWS_WITH(scene_with("x,y,region\n0.0,0.0,clay\n"),
                    Contains("p.csv:2: region = \"clay\" names no [materials.NAME] table of "));
  CHECK_THROWS_WITH(scene_with("x,y,region\n0.0,0.0,sand\n0.004,0.0,sand\n0.0041,0.001,sand\n"),
                    Contains("p.csv:4: the particle at (0.0041, 0.001) m lies") &&
                        Contains("from that of line 3") &&
                        Contains("closer than half the [scene] particle_spacing of "));
  CHECK_THROWS_WITH(scene_with("x,y,region\n1e5,0.0,sand\n"), Contains("p.csv:2: x = 1e5 m lies outside the domain"));
  CHECK_THROWS_WITH(scene_with("x,y,region\n"), Contains("p.csv:1: no particle"));
  std::filesystem::remove_all(dir);
}
