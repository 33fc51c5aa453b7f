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
  o.guard_corrections = work.health.guard_corrections;
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
  const GuardPushes pushed = guard.apply(p, 0.0);
  CHECK(pushed.count == 3);
  CHECK(pushed.past_edge == 0);  // each lies along its wall
  CHECK(p.x[0] == Approx(-5e-4));
  CHECK(p.vx[0] == 0.0);
  CHECK(p.y[1] == Approx(-5e-4));
  CHECK(p.vy[1] == 0.0);
  CHECK(p.x[3] == Approx(0.04));
  CHECK(p.vx[3] == 0.0);
  CHECK(guard.apply(p, 0.0).count == 0);
}

TEST_CASE("the wall guard tells a particle put back past a floor's end from one along it", "[boundaries]") {
  // A floor from x = 0 to 0.1 at y = 0 guarded 6 mm deep: soil that slid off its end and sank 1 mm
  // is put back on the floor's line (within the guard's reach) and counted as past its edge.
  Particles p = test::lattice(2, 1.0e-3, 2000.0);
  p.x[0] = 0.05, p.y[0] = -0.001;   // behind the floor, along it
  p.x[1] = 0.104, p.y[1] = -0.001;  // behind its line, 4 mm past its end
  p.x[2] = 0.2, p.y[2] = -0.001;    // beyond the guard's reach
  p.y[3] = 0.01;
  const WallGuard guard{{{{0.0, 0.0}, {0.1, 0.0}, 0.006, {}}}};
  const GuardPushes pushed = guard.apply(p, 0.0);
  CHECK(pushed.count == 2);
  CHECK(pushed.past_edge == 1);
  CHECK(p.y[1] == Approx(0.0).margin(1e-15));
  CHECK(p.y[2] == -0.001);
}

namespace {
/// The linear-elastic column held by both walls at its geostatic state, 2 mm, with the floor's
/// ghosts continuing the soil's weight (`setup.ghost_body_force`, the default) or not.
struct GeostaticColumn {
  Scene scene = test::scene_from_text(R"(
[scene]
column_width = 0.04
column_height = 0.06
particle_spacing = 0.002
smoothing_ratio = 1.3
end_time = 0.01
gravity = 9.81
floor_length = 0.05
wall_withdrawal = "none"
)" + fixtures::kLinearElasticToml);
  Particles p = build_particles(scene);
  SolverSetup setup = make_solver_setup(scene);
  GeostaticColumn() { set_geostatic_state(p, scene); }
};
}  // namespace

TEST_CASE("a floor ghost carries the geostatic stress of its own depth, a side-wall ghost the soil's",
          "[boundaries]") {
  GeostaticColumn c;
  NeighbourList nl;
  nl.build(c.p.x, c.p.y, c.setup.kernel, c.p.soil_count);
  const double rho = c.p.density[0], g = 9.81, dp = 0.002, top = 0.06 + 0.5 * dp;
  std::size_t floor_ghosts = 0, wall_ghosts = 0;
  for (std::size_t b = c.p.soil_count; b < c.p.size(); ++b) {
    if (nl.pair_count(b) == 0) continue;
    mirror_stress_onto_ghost(c.p, nl, b, c.setup.ghost_body_force);
    const std::size_t k = b - c.p.soil_count;
    if (c.p.wall_ny[k] == 1.0) {
      ++floor_ghosts;
      // Σ_j W (σ_yy,j − ρ g (y_j − y_b)) / Σ_j W with σ_yy,j = −ρ g (top − y_j): exactly −ρ g (top − y_b).
      CHECK(c.p.syy[b] == Approx(-rho * g * (top - c.p.y[b])).epsilon(1e-12));
    } else if (std::abs(c.p.wall_nx[k]) == 1.0) {
      ++wall_ghosts;  // gravity along the wall: g·n = 0, the normal stress is the soil's average
      double w = 0.0, sxx = 0.0;
      nl.for_each_pair(b, [&](const NeighbourList::Pair& q) { w += q.w, sxx += q.w * c.p.sxx[q.j]; });
      CHECK(c.p.sxx[b] == Approx(sxx / w).epsilon(1e-12));
    }
  }
  CHECK(floor_ghosts > 0);
  CHECK(wall_ghosts > 0);
}

namespace {
/// a_y / g after the first step of the held geostatic column, averaged over the soil of lattice row
/// `row` (0 at the floor) away from the side walls.
double row_acceleration(const GeostaticColumn& start, int row) {
  GeostaticColumn c = start;
  Workspace work(c.setup, c.p);
  advance(std::get<LinearElastic>(c.scene.material), c.setup, c.p, work, c.setup.initial_time_step());
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < c.p.soil_count; ++i)
    if (std::abs(c.p.y0[i] - row * 0.002) < 1e-9 && c.p.x0[i] > 0.006 && c.p.x0[i] < 0.034) sum += c.p.ay[i], ++n;
  REQUIRE(n > 0);
  return sum / n / 9.81;
}
}  // namespace

TEST_CASE("the geostatic column is as much in equilibrium at the floor as inside; without the ghosts' "
          "weight its bottom row falls",
          "[boundaries]") {
  // Inside, a_y = (m − 1) g with m the lattice moment of the kernel gradient (1.0105 at h = 1.3 Δp,
  // tests/sph/test_velocity_gradient.cpp): the stress gradient ρg is overestimated by that factor.
  const GeostaticColumn with_weight;
  const double interior = row_acceleration(with_weight, 10);
  CHECK(interior == Approx(0.0105).margin(5e-4));
  for (int row = 0; row < 3; ++row) CHECK(row_acceleration(with_weight, row) == Approx(interior).margin(1e-3));
  GeostaticColumn without;
  without.setup.ghost_body_force = {};
  CHECK(row_acceleration(without, 10) == Approx(interior).margin(1e-12));
  CHECK(row_acceleration(without, 0) < interior - 0.1);  // −0.51 g measured
}
