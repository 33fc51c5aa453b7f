// Histories: the force on each boundary against the statics of the column at rest and against the
// momentum balance at every sample; gauges against the closed-form geostatic stress; the CSV files
// of a resumed run; the [deposit], [[gauges]] and boundary-name keys.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "helpers.h"
#include "../common/material_toml.h"
#include "sph/analysis/boundary_forces.h"
#include "sph/collapse.h"
#include "sph/output/history_writer.h"
#include "../common/temp_dir.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
/// The paper's D-P column at 4 mm with both walls kept, to t = 0.02 s.
Scene kept_column() {
  return test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004", "scene.wall_withdrawal=\"none\"",
                                             "scene.end_time=0.02", "scene.stop_at_rest=false"});
}

struct Sample {
  double time;
  std::vector<Vec2> forces;  ///< by wall index
  Vec2 weight_less_inertia;  ///< M g − Σ m_i a_i
  std::vector<GaugeReading> gauges;
};

std::vector<Sample> sampled_run(const Scene& scene) {
  Collapse collapse(scene);
  const GaugeSet gauges(scene.gauges, collapse.particles(), scene.geometry.particle_spacing,
                        collapse.setup().kernel, scene.source);
  std::vector<Sample> samples;
  RunControl control;
  control.sample_interval = 0.005;
  control.on_sample = [&](const StepSample& s) {
    const Particles& p = s.particles;
    Sample sample{s.time, boundary_forces(p, s.neighbours, s.momentum, scene.geometry.layout.walls.size()), {}, {}};
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      sample.weight_less_inertia.x += p.mass[i] * (s.momentum.gravity.x - p.ax[i]);
      sample.weight_less_inertia.y += p.mass[i] * (s.momentum.gravity.y - p.ay[i]);
    }
    sample.gauges = gauges.read(p, s.v_next);
    samples.push_back(std::move(sample));
  };
  collapse.run(ThreadTuner(1, false), [](const Particles&, double) {}, [](double, std::size_t) {}, control);
  return samples;
}
}  // namespace

TEST_CASE("the walls of a column at rest carry its weight and the K0 thrust, and balance its momentum",
          "[histories][boundary_forces]") {
  const Scene scene = kept_column();
  const std::vector<Sample> samples = sampled_run(scene);
  REQUIRE(samples.size() == 4);  // the first steps at or after t = 0, 0.005, 0.01, 0.015 (it ends at 0.02)
  CHECK(samples.front().time == 0.0);
  // The column: 11 × 16 particles of ρ Δp², the soil from −Δp/2 to H + Δp/2 (its ghosts' surfaces).
  const double rho = 2000.0, g = 9.81, dx = 0.004, height = 0.06 + dx, k0 = 0.3 / 0.7;
  const double weight = 11 * 16 * rho * dx * dx * g, thrust = 0.5 * k0 * rho * g * height * height;
  for (const Sample& s : samples) {
    // Σ_w F_w = M g − Σ m_i a_i: the soil–soil pair terms cancel (boundary_forces.h), to round-off.
    Vec2 total;
    for (const Vec2& f : s.forces) total = total + f;
    CHECK(total.x == Approx(s.weight_less_inertia.x).margin(1e-9 * weight));
    CHECK(total.y == Approx(s.weight_less_inertia.y).margin(1e-9 * weight));
    // Statics: the floor (wall 0) carries the weight, the side walls (1: x = W, 2: x = 0) the
    // thrust K0 ρ g H²/2 outwards, without shear (free slip); within 5 % for the SPH boundary.
    CHECK(s.forces[0].y == Approx(-weight).epsilon(0.05));
    CHECK(s.forces[1].x == Approx(thrust).epsilon(0.05));
    CHECK(s.forces[2].x == Approx(-thrust).epsilon(0.05));
    CHECK(std::abs(s.forces[1].y) < 0.01 * weight);
    CHECK(std::abs(s.forces[2].y) < 0.01 * weight);
  }
}

TEST_CASE("gauges read the geostatic stress of the closed form at t = 0", "[histories][gauges]") {
  // A particle gauge on a lattice node and a point gauge midway between two rows (where the
  // Shepard average of a stress linear in depth is exact on the symmetric lattice), both farther
  // than 2h from the walls and the surface.
  const Scene scene = test::scene_from_text(R"(
[scene]
column_width = 0.04
column_height = 0.06
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.005
gravity = 9.81
wall_withdrawal = "none"
stop_at_rest = false
[[gauges]]
name = "node"
position = [0.02, 0.02]
[[gauges]]
name = "between-rows"
position = [0.021, 0.03]
kind = "point"
)" + fixtures::kDruckerPragerToml);
  const std::vector<Sample> samples = sampled_run(scene);
  REQUIRE(!samples.empty());
  const std::vector<GaugeReading>& at_start = samples.front().gauges;
  REQUIRE(at_start.size() == 2);
  const double rho = 2000.0, g = 9.81, k0 = 0.3 / 0.7, surface = 0.06 + 0.002;
  for (const auto& [reading, y] : {std::pair{at_start[0], 0.02}, std::pair{at_start[1], 0.03}}) {
    const double sv = rho * g * (surface - y);  // compression-positive
    CHECK(reading.p == Approx(sv * (1.0 + 2.0 * k0) / 3.0).epsilon(1e-9));
    CHECK(reading.q == Approx(sv * (1.0 - k0)).epsilon(1e-9));
    CHECK(reading.displacement.x == 0.0);
    CHECK(std::abs(reading.displacement.y) < 1e-12);
  }
  CHECK(at_start[0].position.x == 0.02);
  CHECK(at_start[1].position.x == 0.021);
}

TEST_CASE("a gauge outside the soil, a gauge named twice, a boundary named twice and a deposit direction "
          "along gravity are refused", "[histories][scene]") {
  const std::string column = R"(
[scene]
column_width = 0.04
column_height = 0.06
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.01
gravity = 9.81
wall_withdrawal = "instant"
)";
  const std::string& material = fixtures::kDruckerPragerToml;
  const Scene outside = test::scene_from_text(column + "[[gauges]]\nname = \"air\"\nposition = [0.02, 0.08]\n" + material);
  const Particles p = build_particles(outside);
  CHECK_THROWS_WITH(GaugeSet(outside.gauges, p, 0.004, CubicSpline(0.0052), outside.source),
                    Contains("case.toml: [[gauges]] air: no soil particle within one spacing"));
  CHECK_THROWS_WITH(test::scene_from_text(column + "[[gauges]]\nname = \"a\"\nposition = [0.02, 0.02]\n" +
                                          "[[gauges]]\nname = \"a\"\nposition = [0.02, 0.03]\n" + material),
                    Contains("[gauges #2] name: \"a\" names another gauge too"));
  CHECK_THROWS_WITH(test::scene_from_text(column + "[[boundaries]]\nname = \"floor\"\nkind = \"no-slip\"\n" +
                                          "points = [[0.1, 0.0], [0.2, 0.0]]\n" + material),
                    Contains("name = \"floor\" is also the name of [scene] floor"));
  CHECK_THROWS_WITH(test::scene_from_text(column + "[deposit]\ndirection = [0.0, -2.0]\n" + material),
                    Contains("[deposit] direction: is along gravity"));
  // The defaults: the column's measures, unnamed boundaries numbered.
  const Scene plain = test::scene_from_text(column + "[[boundaries]]\nkind = \"no-slip\"\npoints = [[0.1, 0.0], [0.2, 0.0]]\n" + material);
  CHECK(plain.deposit.origin == Vec2{0.04, 0.0});
  CHECK(plain.deposit.direction == Vec2{-1.0, 0.0});
  CHECK(plain.deposit.up == Vec2{0.0, 1.0});
  CHECK(plain.deposit.toe_thickness == Approx(0.006));
  CHECK(plain.geometry.layout.walls.back().label == "boundary_1");
}

TEST_CASE("a resumed run's histories keep the rows before its checkpoint and drop later and torn ones",
          "[histories][resume]") {
  const soilsph::testing::TempDir scratch("soilsph-histories");
  const std::filesystem::path dir = scratch / "run";
  {
    HistoryWriter w(dir, {"floor", "wall"}, {"g"}, "per metre");
    for (const double t : {0.0, 0.1, 0.2}) {
      const Vec2 forces[] = {{1.0, -t}, {2.0, t}};
      const GaugeReading readings[] = {{{t, 0.0}, {}, {}, 1.0, 2.0}};
      w.write(t, forces, readings, {.kinetic = t, .potential = -2.0 * t});
    }
  }
  std::ofstream(dir / HistoryWriter::kBoundaryFile, std::ios::app) << "0.3,floor,1.";  // killed mid-row
  HistoryWriter resumed = HistoryWriter::continuing(dir, {"floor", "wall"}, {"g"}, "per metre", 0.15);
  CHECK(resumed.last_sample() == 0.1);
  const Vec2 forces[] = {{3.0, 3.0}, {4.0, 4.0}};
  const GaugeReading readings[] = {{{0.0, 0.0}, {}, {}, 5.0, 6.0}};
  resumed.write(0.15, forces, readings, {.kinetic = 1.0, .potential = 0.5});
  const auto data_rows = [&](const char* name) {
    std::ifstream in(dir / name);
    std::vector<std::string> rows;
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line.front() != '#') rows.push_back(line);
    return rows;
  };
  const std::vector<std::string> forces_rows = data_rows(HistoryWriter::kBoundaryFile);
  REQUIRE(forces_rows.size() == 7);  // the header, t = 0 and 0.1 for two walls, t = 0.15 for two
  CHECK(forces_rows[0] == "time_s,boundary,fx_N_per_m,fy_N_per_m");
  CHECK(forces_rows[4] == "0.1,wall,2,0.1");
  CHECK(forces_rows[5] == "0.15,floor,3,3");
  const std::vector<std::string> gauge_rows = data_rows(HistoryWriter::kGaugeFile);
  REQUIRE(gauge_rows.size() == 4);
  CHECK(gauge_rows[3] == "0.15,g,0,0,0,0,0,0,5,6");
  const std::vector<std::string> energy_rows = data_rows(HistoryWriter::kEnergyFile);
  REQUIRE(energy_rows.size() == 4);
  CHECK(energy_rows[0] == "time_s,kinetic_J_per_m,potential_J_per_m,mechanical_J_per_m");
  CHECK(energy_rows[2] == "0.1,0.1,-0.2,-0.1");
  CHECK(energy_rows[3] == "0.15,1,0.5,1.5");
  std::filesystem::remove_all(dir);
}
