// Ghost particles stop soil moving at a wall, without the last-line guard having to act.
#include <catch2/catch.hpp>

#include <algorithm>

#include "helpers.h"
#include "../common/material_toml.h"
#include "sph/diagnostics.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
// A small, weightless linear-elastic block between the walls, at rest and stress-free.
const std::string kBlock = R"(
[scene]
column_width = 0.016
column_height = 0.016
particle_spacing = 0.002
smoothing_ratio = 1.3
end_time = 0.04
gravity = 0.0
wall_withdrawal = "none"
floor_length = 0.03
)" + fixtures::kLinearElasticToml;

struct Outcome {
  double deepest_penetration;  ///< largest distance beyond the wall surface reached (m), ≤ 0 if none
  double final_velocity;       ///< mean velocity component into the wall at the end (m/s)
  std::size_t guard_corrections;
};

/// Throws the block at the wall with speed v0 (into the floor or into the fixed wall) and runs.
Outcome throw_block(bool at_floor, double v0) {
  const Scene scene = test::scene_from_text(kBlock);
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  for (std::size_t i = 0; i < p.soil_count; ++i) (at_floor ? p.vy[i] : p.vx[i]) = at_floor ? -v0 : v0;
  const SolverSetup setup = make_solver_setup(scene);
  Workspace work(setup, p);
  Outcome o{-1.0, 0.0, 0};
  const double dt = setup.initial_time_step();
  for (double t = 0.0; t < setup.end_time; t += dt) {
    advance(std::get<LinearElastic>(scene.material), setup, p, work, dt);
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      // The floor surface y = −Δp/2, the fixed wall's x = W + Δp/2 (geometry/column.h).
      const double beyond = at_floor ? -0.001 - p.y[i] : p.x[i] - (0.016 + 0.001);
      o.deepest_penetration = std::max(o.deepest_penetration, beyond);
    }
  }
  double v = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) v += at_floor ? -p.vy[i] : p.vx[i];
  o.final_velocity = v / static_cast<double>(p.soil_count);
  o.guard_corrections = work.guard_corrections;
  REQUIRE(all_finite(p));
  return o;
}
}  // namespace

TEST_CASE("the floor's ghost particles stop a block thrown at it", "[boundaries]") {
  const double v0 = 0.5;  // m/s, about the largest speed in the collapse
  const Outcome o = throw_block(true, v0);
  CHECK(o.guard_corrections == 0);
  CHECK(o.deepest_penetration < 0.0);  // never reaches the floor surface, half a spacing below y = 0
  CHECK(o.final_velocity < 0.5 * v0);  // stopped or bouncing back
}

TEST_CASE("the fixed wall's ghost particles stop a block thrown at it", "[boundaries]") {
  const double v0 = 0.5;
  const Outcome o = throw_block(false, v0);
  CHECK(o.guard_corrections == 0);
  CHECK(o.deepest_penetration < 0.0);
  CHECK(o.final_velocity < 0.5 * v0);
}

TEST_CASE("the wall guard puts back a particle found beyond a wall", "[boundaries]") {
  Particles p = test::lattice(2, 1.0e-3, 2000.0);
  p.x[0] = -0.01, p.vx[0] = -1.0;  // beyond the left wall, moving out
  p.y[1] = -0.01, p.vy[1] = -1.0;  // below the floor, moving down
  p.x[3] = 0.05, p.vx[3] = 2.0;    // beyond the right wall
  // The column's three walls as surfaces with the soil on their left: floor, fixed, removable.
  const double depth = 0.02;
  const WallGuard guard{{{{-0.3, -5e-4}, {0.04, -5e-4}, depth, {}},
                         {{0.04, -5e-4}, {0.04, 0.1}, depth, {}},
                         {{-5e-4, 0.1}, {-5e-4, -5e-4}, depth, {}}}};
  CHECK(guard.apply(p, 0.0) == 3);
  CHECK(p.x[0] == Approx(-5e-4));
  CHECK(p.vx[0] == 0.0);
  CHECK(p.y[1] == Approx(-5e-4));
  CHECK(p.vy[1] == 0.0);
  CHECK(p.x[3] == Approx(0.04));
  CHECK(p.vx[3] == 0.0);
  CHECK(guard.apply(p, 0.0) == 0);
}
