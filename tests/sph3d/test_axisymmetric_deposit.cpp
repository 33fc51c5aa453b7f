// The axisymmetric deposit measures on synthetic deposits with known answers (a cylinder built on
// rings, a cone on the lattice, splashed grains), and Lube et al.'s (2004) laws.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sph/analysis/axisymmetric_deposit.h"

using namespace soilsph::sph;

namespace {
/// A cylinder of radius R = rings·dx and height layers·dx (its top layer's cells reach that high)
/// standing on the floor z = 0 about the z axis: layer centres at (k + ½) dx, each layer a centre particle
/// and rings of radius m·dx with 8m particles at azimuths (j + ½) 360°/8m (so each 10° sector at the outer
/// ring holds one or more).
std::vector<Vec3> ring_cylinder(int rings, int layers, double dx) {
  std::vector<Vec3> p;
  for (int k = 0; k < layers; ++k) {
    const double z = (k + 0.5) * dx;
    p.push_back({0, 0, z});
    for (int m = 1; m <= rings; ++m)
      for (int j = 0; j < 8 * m; ++j) {
        const double theta = 2.0 * std::numbers::pi * (j + 0.5) / (8 * m);
        p.push_back({m * dx * std::cos(theta), m * dx * std::sin(theta), z});
      }
  }
  return p;
}
const DepositAxis kZAxis{
    .point = {0, 0, 0}, .up = {0, 0, 1}, .azimuth_zero = {1, 0, 0}, .azimuth_quarter = {0, 1, 0}};
}  // namespace

TEST_CASE("a cylinder deposit: runout R in every sector, no spread, height of its top layer's cells",
          "[geometry3d]") {
  const double dx = 0.002;
  std::vector<Vec3> soil = ring_cylinder(15, 6, dx);
  AxisymmetricDeposit d = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, default_sectors(360.0));
  REQUIRE(d.sector_runout_m.size() == 36);
  CHECK(d.runout_radius_m == Approx(15 * dx).epsilon(1e-12));
  CHECK(d.runout_radius_spread_m == Approx(0.0).margin(1e-15));
  CHECK(d.height_m == Approx(6 * dx).epsilon(1e-12));
  // Splashed grains: one on the floor 5 spacings beyond the rim at 3°, one 5 spacings above the axis,
  // one in the air over the rim: none changes the measures.
  soil.push_back({20 * dx * std::cos(0.05), 20 * dx * std::sin(0.05), 0.5 * dx});
  soil.push_back({0, 0, 10.5 * dx});
  soil.push_back({16 * dx, 0, 3 * dx});
  d = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36);
  CHECK(d.runout_radius_m == Approx(15 * dx).epsilon(1e-12));
  CHECK(d.height_m == Approx(6 * dx).epsilon(1e-12));
  // A grain riding 1.3 spacings above the floor beyond the rim, as the sheet beyond a deposit's
  // edge does, is not in the bottom layer; one on the floor within two spacings of the rim is part
  // of the body: sector 0's runout grows to 16.5 dx, the mean by 1.5 dx / 36, the spread to 1.5 dx.
  soil.push_back({17.5 * dx * std::cos(0.05), 17.5 * dx * std::sin(0.05), 1.3 * dx});
  d = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36);
  CHECK(d.runout_radius_m == Approx(15 * dx).epsilon(1e-12));
  soil.push_back({16.5 * dx * std::cos(0.05), 16.5 * dx * std::sin(0.05), 0.5 * dx});
  d = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36);
  CHECK(d.sector_runout_m[0] == Approx(16.5 * dx));
  CHECK(d.runout_radius_m == Approx(15 * dx + 1.5 * dx / 36));
  CHECK(d.runout_radius_spread_m == Approx(1.5 * dx));
}

TEST_CASE("a lattice cone in a quarter domain, y up: runout and height within a spacing", "[geometry3d]") {
  // The cone r ≤ R (1 − h/Hc) on the lattice (i + ½, j + ½, k + ½) dx of the quarter x, z > 0 with
  // y up. Its bottom row (h = dx/2) reaches R_b = R (1 − dx/(2 Hc)), and each 10° sector at that
  // radius (3.3 dx wide) holds a node within a spacing inside it; the top of the top node's cell near
  // the axis lies within a spacing below Hc or half a spacing above it.
  const double dx = 0.001, R = 0.02, Hc = 0.01;
  std::vector<Vec3> soil;
  for (int j = 0; (j + 0.5) * dx < Hc; ++j)
    for (int k = 0; (k + 0.5) * dx < R; ++k)
      for (int i = 0; (i + 0.5) * dx < R; ++i) {
        const Vec3 p{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx};
        if (std::hypot(p.x, p.z) <= R * (1.0 - p.y / Hc)) soil.push_back(p);
      }
  const DepositAxis axis{
      .point = {0, 0, 0}, .up = {0, 1, 0}, .azimuth_zero = {1, 0, 0}, .azimuth_quarter = {0, 0, 1}};
  const AxisymmetricDeposit d = measure_axisymmetric_deposit(soil, axis, dx, 90.0, default_sectors(90.0));
  REQUIRE(d.sector_runout_m.size() == 9);
  const double bottom_reach = R * (1.0 - 0.5 * dx / Hc);
  for (const double r : d.sector_runout_m) {
    CHECK(r <= bottom_reach);
    CHECK(r > bottom_reach - dx);
  }
  CHECK(d.runout_radius_spread_m < dx);
  CHECK(d.height_m <= Hc + 0.5 * dx);
  CHECK(d.height_m > Hc - dx);
}

TEST_CASE("the thick runout radius: the outermost strip a toe thickness thick, the thin edge left out",
          "[geometry3d]") {
  // A cylinder of radius 15 dx and 6 layers (6 dx thick) with a sheet one particle thick around it
  // out to 25 dx, its particles at 0.9 dx above the floor (cell tops at 1.4 dx). At t = 3 dx
  // every sector's outermost strip that thick is the cylinder's rim, at 15 dx; at t = 1.2 dx the
  // sheet counts, out to 25 dx; the runout radius, within the bottom layer, reaches the sheet's edge
  // whatever t.
  const double dx = 0.002;
  std::vector<Vec3> soil = ring_cylinder(15, 6, dx);
  for (int m = 16; m <= 25; ++m)
    for (int j = 0; j < 8 * m; ++j) {
      const double theta = 2.0 * std::numbers::pi * (j + 0.5) / (8 * m);
      soil.push_back({m * dx * std::cos(theta), m * dx * std::sin(theta), 0.9 * dx});
    }
  const AxisymmetricDeposit body = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36, 3.0 * dx);
  CHECK(body.runout_radius_thick_m == Approx(15 * dx).epsilon(1e-12));
  CHECK(body.runout_radius_m == Approx(25 * dx).epsilon(1e-12));
  const AxisymmetricDeposit sheet = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36, 1.2 * dx);
  CHECK(sheet.runout_radius_thick_m == Approx(25 * dx).epsilon(1e-12));
  CHECK(std::isnan(measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36).runout_radius_thick_m));
  // Grains thrown off the front, as a fine run's are: one in the air 40 dx out in sector 0, one over
  // the sheet in sector 1 (9 dx up) and one over the body in sector 2 (3 spacings above its top). No
  // strip's soil held up from the floor reaches them: the thick runout stays the rim.
  const auto at = [&](double r, double degrees, double z) {
    const double a = degrees * std::numbers::pi / 180.0;
    return Vec3{r * std::cos(a), r * std::sin(a), z};
  };
  soil.push_back(at(40 * dx, 5.0, 4 * dx));
  soil.push_back(at(20 * dx, 15.0, 9 * dx));
  soil.push_back(at(10 * dx, 25.0, 9.5 * dx));
  const AxisymmetricDeposit thrown = measure_axisymmetric_deposit(soil, kZAxis, dx, 360.0, 36, 3.0 * dx);
  CHECK(thrown.runout_radius_thick_m == Approx(15 * dx).epsilon(1e-12));
}

TEST_CASE("no soil on the axis: height 0; bad input is refused", "[geometry3d]") {
  const double dx = 0.001;
  const std::vector<Vec3> ring{{0.01, 0, 0.0005}, {0, 0.01, 0.0005}, {-0.01, 0, 0.0005}, {0, -0.01, 0.0005}};
  CHECK(measure_axisymmetric_deposit(ring, kZAxis, dx, 360.0, 4).height_m == 0.0);
  const std::vector<Vec3> floating{{0, 0, 0.05}};
  CHECK(measure_axisymmetric_deposit(floating, kZAxis, dx, 360.0, 1).height_m == 0.0);
  CHECK_THROWS_AS(measure_axisymmetric_deposit({}, kZAxis, dx, 360.0, 4), std::invalid_argument);
  CHECK_THROWS_AS(measure_axisymmetric_deposit(ring, kZAxis, 0.0, 360.0, 4), std::invalid_argument);
  CHECK_THROWS_AS(measure_axisymmetric_deposit(ring, kZAxis, dx, 400.0, 4), std::invalid_argument);
  CHECK_THROWS_AS(measure_axisymmetric_deposit(ring, kZAxis, dx, 90.0, 0), std::invalid_argument);
}

TEST_CASE("Lube et al. (2004): runout, height and time to rest against the aspect ratio", "[geometry3d]") {
  CHECK(lube2004::runout_ratio(0.5) == Approx(0.62));
  CHECK(lube2004::runout_ratio(1.0) == Approx(1.24));
  CHECK(lube2004::runout_ratio(4.0) == Approx(3.2));  // 1.6 √4
  CHECK(lube2004::height_ratio(0.5) == Approx(0.5));  // H∞ = H0
  CHECK(lube2004::height_ratio(2.0) == Approx(0.88 * std::pow(2.0, 1.0 / 6.0)));
  CHECK(lube2004::height_ratio(1.0) == Approx(0.88));
  CHECK(lube2004::time_to_rest(0.1, 9.81) == Approx(3.0 * std::sqrt(0.1 / 9.81)));
}
