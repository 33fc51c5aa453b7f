// Planar walls: their outlines, the ghost lattice behind them (counts in closed form at inner and
// outer corners), and the mirror of the soil across an oblique plane against hand-computed values.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>

#include "constitutive/parameters.h"
#include "sph/geometry/planar_ghosts.h"
#include "sph/geometry/wall_mirror.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
/// The smallest distance between two of the points (by a cell hash, cells of `dx`).
double closest_pair(const std::vector<GhostPoint3>& ghosts, double dx) {
  std::map<std::array<long long, 3>, std::vector<Vec3>> cells;
  const auto cell = [dx](Vec3 p) {
    return std::array<long long, 3>{std::llround(std::floor(p.x / dx)), std::llround(std::floor(p.y / dx)),
                                    std::llround(std::floor(p.z / dx))};
  };
  double closest = std::numeric_limits<double>::infinity();
  for (const GhostPoint3& g : ghosts) {
    const auto c = cell(g.position);
    for (long long i = -1; i <= 1; ++i)
      for (long long j = -1; j <= 1; ++j)
        for (long long k = -1; k <= 1; ++k)
          if (auto it = cells.find({c[0] + i, c[1] + j, c[2] + k}); it != cells.end())
            for (const Vec3& q : it->second) closest = std::min(closest, norm(g.position - q));
    cells[c].push_back(g.position);
  }
  return closest;
}

/// The six faces of the cube [0, a]³ as walls holding the soil inside.
std::vector<PlanarWall> box_of_walls(double a, bool with_lid) {
  const Vec3 X{a, 0, 0}, Y{0, a, 0}, Z{0, 0, a}, O{};
  std::vector<PlanarWall> walls{
      rectangle_wall(O, X, Y, "floor"),  // the soil on the side of X × Y = +z
      rectangle_wall(O, Z, X, "y = 0"), rectangle_wall(O, Y, Z, "x = 0"),
      rectangle_wall(X, Z, Y, "x = a"), rectangle_wall(Y, X, Z, "y = a"),
  };
  if (with_lid) walls.push_back(rectangle_wall(Z, Y, X, "lid"));
  return walls;
}
}  // namespace

TEST_CASE("a planar wall: its normal points into the soil, its outline is validated", "[geometry3d]") {
  const PlanarWall floor = rectangle_wall({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "floor");
  CHECK(floor.inward == Vec3{0, 0, 1});
  CHECK(floor.height_above({0.3, 0.4, 0.5}) == 0.5);
  CHECK(floor.outline.size() == 4);
  const Vec3 tilted[3] = {{0, 0, 0}, {2, -1, 0}, {0, 1, -1}};  // the plane x + 2y + 2z = 0
  const PlanarWall oblique = make_planar_wall(tilted, "oblique");
  CHECK(oblique.inward.x == Approx(1.0 / 3.0));
  CHECK(oblique.inward.y == Approx(2.0 / 3.0));
  CHECK(oblique.inward.z == Approx(2.0 / 3.0));
  const Vec3 two[2] = {{0, 0, 0}, {1, 0, 0}};
  CHECK_THROWS_WITH(make_planar_wall(two, "s.toml: [[walls]] 3"), Contains("s.toml: [[walls]] 3: 2 points"));
  const Vec3 warped[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}};
  CHECK_THROWS_WITH(make_planar_wall(warped, "w"), Contains("off the plane of the others"));
  const Vec3 bow_tie[5] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, -1, 0}, {0, 2, 0}};  // edge 3 crosses edge 1
  CHECK_THROWS_WITH(make_planar_wall(bow_tie, "w"), Contains("w: the outline is not simple"));
}

TEST_CASE("ghosts of a closed box of walls around a cube of soil: (n + 2L)^3 - n^3", "[geometry3d]") {
  const double dx = 0.001;
  const int n = 10, layers = 3;
  const Lattice3 lattice{.origin = {dx / 2, dx / 2, dx / 2}, .spacing = dx};  // soil nodes (i + 1/2) dx
  for (const bool lid : {true, false}) {
    std::vector<PlanarWall> walls = box_of_walls(n * dx, lid);
    for (PlanarWall& w : walls)  // each wall must face the cube's centre
      REQUIRE(w.height_above({n * dx / 2, n * dx / 2, n * dx / 2}) > 0.0);
    const std::vector<GhostPoint3> ghosts = planar_ghost_points(walls, lattice, layers);
    // With a lid: the shell [−L, n + L)³ less the soil [0, n)³ in node indices. Open at the top, the
    // side walls stop at the top of the soil: [−L, n + L)² × [−L, n) less the soil.
    const int expected = lid ? (n + 2 * layers) * (n + 2 * layers) * (n + 2 * layers) - n * n * n
                             : (n + 2 * layers) * (n + 2 * layers) * (n + layers) - n * n * n;
    CHECK(ghosts.size() == static_cast<std::size_t>(expected));
    CHECK(closest_pair(ghosts, dx) >= 0.5 * dx);
    for (const GhostPoint3& g : ghosts) {
      const bool in_soil = g.position.x > 0 && g.position.x < n * dx && g.position.y > 0 &&
                           g.position.y < n * dx && g.position.z > 0 && g.position.z < n * dx;
      CHECK(!in_soil);
      CHECK(walls[static_cast<std::size_t>(g.wall)].height_above(g.position) < 0.0);  // behind its own wall
    }
  }
}

TEST_CASE("ghosts at an outer corner: a floor stepping down, no ghost in the soil", "[geometry3d]") {
  // In x–z: the upper floor z = 0 over −a ≤ x ≤ 0, a riser x = 0 down to z = −b, the lower floor
  // z = −b over 0 ≤ x ≤ a; all span 0 ≤ y ≤ w. The soil lies above the floors and at x > 0. With
  // A = a/dx, B = b/dx, W = w/dx: the upper floor's slab A·L (not grown at the riser: an outer
  // corner), the riser's L·(B + L) grown down into the lower floor's corner, the lower floor's
  // (A + L)·L grown under the riser, less the two L·L blocks claimed twice: (2A + B)·L per W.
  const double dx = 0.001;
  const int A = 8, B = 5, W = 4, L = 2;
  const double a = A * dx, b = B * dx, w = W * dx;
  const std::vector<PlanarWall> walls{
      rectangle_wall({-a, 0, 0}, {a, 0, 0}, {0, w, 0}, "upper floor"),
      rectangle_wall({0, 0, -b}, {0, w, 0}, {0, 0, b}, "riser"),
      rectangle_wall({0, 0, -b}, {a, 0, 0}, {0, w, 0}, "lower floor"),
  };
  REQUIRE(walls[0].inward == Vec3{0, 0, 1});
  REQUIRE(walls[1].inward.x == Approx(1.0));
  REQUIRE(walls[2].inward == Vec3{0, 0, 1});
  const std::vector<GhostPoint3> ghosts =
      planar_ghost_points(walls, {.origin = {dx / 2, dx / 2, dx / 2}, .spacing = dx}, L);
  CHECK(ghosts.size() == static_cast<std::size_t>((2 * A + B) * L * W));
  CHECK(closest_pair(ghosts, dx) >= 0.5 * dx);
  for (const GhostPoint3& g : ghosts) {
    const Vec3 p = g.position;
    const bool in_soil = (p.x < 0 && p.z > 0) || (p.x > 0 && p.z > -b);
    CHECK(!in_soil);
  }
}

TEST_CASE("the mirror across an oblique plane, by hand", "[geometry3d]") {
  const Vec3 n{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};  // the plane x + 2y + 2z = 0 through the origin
  // (1, 1, 1) lies 5/3 in front: its image 2·5/3 n behind, (−1/9, −11/9, −11/9).
  const Vec3 image = mirror_point({1, 1, 1}, {0, 0, 0}, n);
  CHECK(image.x == Approx(-1.0 / 9.0));
  CHECK(image.y == Approx(-11.0 / 9.0));
  CHECK(image.z == Approx(-11.0 / 9.0));
  CHECK(norm(mirror_point(image, {0, 0, 0}, n) - Vec3{1, 1, 1}) < 1e-15);

  // The soil moving at v̄ = (1, 0, 0) over a wall at rest: Δv·n = 1/3, slip (8, −2, −2)/9.
  const Vec3 v{1, 0, 0};
  const Vec3 free_slip = ghost_velocity(v, {}, n, 0.0);  // normal part mirrored, slip kept
  CHECK(free_slip.x == Approx(7.0 / 9.0));
  CHECK(free_slip.y == Approx(-4.0 / 9.0));
  CHECK(free_slip.z == Approx(-4.0 / 9.0));
  const Vec3 no_slip = ghost_velocity(v, {}, n, 1.0);  // −v̄
  CHECK(norm(no_slip - Vec3{-1, 0, 0}) < 1e-15);
  // A moving no-slip wall: 2 v_w − v̄.
  const Vec3 moving = ghost_velocity(v, {0, 0.5, 0}, n, 1.0);
  CHECK(norm(moving - Vec3{-1, 1, 0}) < 1e-15);

  // Under a pressure of 100 Pa (σ̄ = −100 I, no shear on the wall):
  const Eigen::Matrix3d pressure = -100.0 * Eigen::Matrix3d::Identity();
  const double inf = std::numeric_limits<double>::infinity(), stick_slip = 1e-4;
  const WallShear free = wall_shear(pressure, n, v, 0.0, stick_slip);
  CHECK(free.stick == 0.0);
  CHECK(norm(free.traction) == 0.0);
  CHECK(ghost_stress(pressure, n, free.traction).isApprox(pressure));
  const WallShear stuck = wall_shear(pressure, n, v, inf, stick_slip);
  CHECK(stuck.stick == 1.0);
  // Frictional, μ = 0.5, sliding along the slip (8, −2, −2)/9 of length 2√2/3: τ = 50 Pa along it.
  const WallShear sliding = wall_shear(pressure, n, v, 0.5, stick_slip);
  CHECK(sliding.stick == 0.0);
  const double along = 50.0 / (6.0 * std::sqrt(2.0));  // 50 / |(8, −2, −2)|
  CHECK(sliding.traction.x == Approx(8 * along));
  CHECK(sliding.traction.y == Approx(-2 * along));
  CHECK(sliding.traction.z == Approx(-2 * along));
  const Eigen::Matrix3d ghost = ghost_stress(pressure, n, sliding.traction);
  // σ_b = σ̄ + 2(τ⊗n + n⊗τ): σ_xx = −100 + 4 τ_x n_x = −100 + 400√2/9, σ_yz = 2(τ_y n_z + n_y τ_z).
  CHECK(ghost(0, 0) == Approx(-100.0 + 400.0 * std::sqrt(2.0) / 9.0));
  CHECK(ghost(1, 2) == Approx(2.0 * (-2 * along * 2.0 / 3.0 + 2.0 / 3.0 * -2 * along)));
  const Eigen::Vector3d nn{n.x, n.y, n.z}, traction = ghost * nn;
  CHECK(nn.dot(traction) == Approx(-100.0));  // the normal stress carries over
  // Its shear traction is 2τ: the average across the wall is τ.
  const Eigen::Vector3d shear = traction - nn.dot(traction) * nn;
  CHECK(shear.x() == Approx(2 * 8 * along));
  CHECK(shear.y() == Approx(2 * -2 * along));

  // At rest (no slip) under a shear the wall can hold, it sticks: τ = τ̄. σ̄ = −100 I + 10 (e_x⊗e_y
  // + e_y⊗e_x): σ̄n = (−80, −190, −200)/3, n·σ̄n = −100 + 40/9, τ̄ = (140, 10, −80)/27 of length
  // 5.98 < 0.5 (100 − 40/9) = 47.8.
  Eigen::Matrix3d sheared = pressure;
  sheared(0, 1) = sheared(1, 0) = 10.0;
  const WallShear holding = wall_shear(sheared, n, {}, 0.5, stick_slip);
  CHECK(holding.stick == 1.0);
  const Eigen::Vector3d t_full = sheared * nn, tau_soil = t_full - nn.dot(t_full) * nn;
  CHECK(tau_soil.x() == Approx(140.0 / 27.0));
  CHECK(holding.traction.x == Approx(140.0 / 27.0));
  CHECK(holding.traction.z == Approx(-80.0 / 27.0));
  CHECK(ghost_stress(sheared, n, holding.traction).isApprox(sheared));  // no slip copies the stress
  // Beyond the limit (μ = 0.05: 4.78 Pa < |τ̄|) it slides along τ̄ at the limit.
  const WallShear yielding = wall_shear(sheared, n, {}, 0.05, stick_slip);
  CHECK(yielding.stick == 0.0);
  CHECK(yielding.traction.y / yielding.traction.x == Approx(10.0 / 140.0));
  CHECK(norm(yielding.traction) == Approx(0.05 * (100.0 - 40.0 / 9.0)));
  // A wall in tension holds no shear.
  CHECK(norm(wall_shear(-pressure, n, v, 0.5, stick_slip).traction) == 0.0);
}
