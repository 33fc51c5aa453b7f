// Deposit metrics on synthetic particle sets whose runout, height and slope are known by construction.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "sph/analysis/deposit.h"

using soilsph::sph::measure_deposit;

namespace {

constexpr double kWall = 0.04;     // fixed wall x = W, as in the paper's column
constexpr double kSpacing = 1e-3;  // particle spacing

double degrees(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

struct Particles {
  std::vector<double> x, y;
  void add(double px, double py) {
    x.push_back(px);
    y.push_back(py);
  }
  /// A vertical column of particles from the floor to exactly height h, spaced ≤ kSpacing, so that
  /// its top particle lies on the surface y = h.
  void add_column(double px, double h) {
    if (h <= 0) return add(px, 0.0);
    const int intervals = std::max(1, static_cast<int>(std::ceil(h / kSpacing - 1e-9)));
    for (int j = 0; j <= intervals; ++j) add(px, h * j / intervals);
  }
  /// Columns at x = W − k·spacing, k = 0..columns−1, with heights profile(x).
  void add_profile(int columns, const std::function<double(double)>& profile) {
    for (int k = 0; k < columns; ++k) {
      const double px = kWall - k * kSpacing;
      add_column(px, profile(px));
    }
  }
  soilsph::sph::DepositMetrics measure() const { return measure_deposit(x, y, kWall, kSpacing); }
};

}  // namespace

TEST_CASE("a rectangle: runout = width, height = height, a vertical face", "[deposit]") {
  // The paper's initial column: 41 × 61 particles at 1 mm, edges on x = 0, W and y = 0, H.
  Particles column;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 60; ++j) column.add(i * kSpacing, j * kSpacing);
  }
  const auto m = column.measure();
  CHECK(m.runout_m == Approx(0.04).epsilon(1e-12));
  CHECK(m.height_m == Approx(0.06).epsilon(1e-12));
  CHECK(m.repose_angle_deg == 90.0);
}

TEST_CASE("a triangle of known slope: runout, height and angle exact", "[deposit]") {
  for (const double angle : {20.0, 30.0, 45.0}) {
    const double slope = std::tan(angle * std::numbers::pi / 180.0);
    const int columns = 101;  // toe at x = W − 100 mm
    const double toe = kWall - (columns - 1) * kSpacing;
    Particles pile;
    pile.add_profile(columns, [&](double px) { return slope * (px - toe); });
    const auto m = pile.measure();
    CHECK(m.runout_m == Approx(0.1).epsilon(1e-12));
    CHECK(m.height_m == Approx(slope * 0.1).epsilon(1e-12));
    CHECK(m.repose_angle_deg == Approx(angle).epsilon(1e-9));
  }
}

TEST_CASE("isolated splashed particles change neither runout, height nor angle", "[deposit]") {
  const double slope = std::tan(30.0 * std::numbers::pi / 180.0);
  const double toe = kWall - 100 * kSpacing;
  Particles pile;
  pile.add_profile(101, [&](double px) { return slope * (px - toe); });
  const auto clean = pile.measure();

  Particles splashed = pile;
  splashed.add(toe - 0.05, 0.0);                                             // far ahead on the floor
  splashed.add(toe - 2.5 * kSpacing, 0.0);                                   // just beyond the 2-spacing link
  splashed.add(kWall - 0.01, slope * 0.09 + 0.02);                           // flying 2 cm above the surface
  for (int k = 0; k < 5; ++k) splashed.add(toe - 0.02 - k * kSpacing, 0.0);  // a small detached group
  const auto m = splashed.measure();
  CHECK(m.runout_m == Approx(clean.runout_m).epsilon(1e-12));
  CHECK(m.height_m == Approx(clean.height_m).epsilon(1e-12));
  CHECK(m.repose_angle_deg == Approx(30.0).epsilon(1e-9));
}

TEST_CASE("a particle within the link distance of the toe belongs to the deposit", "[deposit]") {
  const double toe = kWall - 100 * kSpacing;
  Particles pile;
  pile.add_profile(101, [&](double px) { return 0.5 * (px - toe); });
  Particles near = pile, far = pile;
  near.add(toe - 1.9 * kSpacing, 0.0);
  far.add(toe - 2.1 * kSpacing, 0.0);
  CHECK(near.measure().runout_m == Approx(0.1 + 1.9 * kSpacing).epsilon(1e-12));
  CHECK(far.measure().runout_m == Approx(0.1).epsilon(1e-12));
}

TEST_CASE("a slab's deposit links its body in space: lone particles of different layers do not chain",
          "[deposit]") {
  // The pile above extruded over five layers z = 0 … 4 spacings, and beyond its toe a line of lone
  // particles 1.5 spacings apart along x that alternate between the last and the first layer: seen
  // along z they chain to the toe (gaps of 1.5 ≤ 2 spacings), in space each lies 4.3 spacings from
  // the next, and only the first is within the link distance of the pile (of its last layer's
  // toe). One more particle 1.9 spacings beyond the toe in the middle layer joins the pile too.
  const double toe = kWall - 100 * kSpacing;
  Particles pile;
  pile.add_profile(101, [&](double px) { return 0.5 * (px - toe); });
  std::vector<double> x, y, z;
  for (int layer = 0; layer < 5; ++layer) {
    x.insert(x.end(), pile.x.begin(), pile.x.end());
    y.insert(y.end(), pile.y.begin(), pile.y.end());
    z.insert(z.end(), pile.x.size(), layer * kSpacing);
  }
  for (int k = 1; k <= 20; ++k) {
    x.push_back(toe - 1.5 * k * kSpacing);
    y.push_back(0.0);
    z.push_back(k % 2 == 0 ? 0.0 : 4 * kSpacing);
  }
  const auto slab = soilsph::sph::measure_slab_deposit(x, y, z, kWall, kSpacing);
  CHECK(slab.runout_m == Approx(0.1 + 1.5 * kSpacing).epsilon(1e-12));
  CHECK(slab.height_m == Approx(pile.measure().height_m).epsilon(1e-12));
  CHECK(slab.repose_angle_deg == Approx(pile.measure().repose_angle_deg).epsilon(1e-12));
  CHECK(measure_deposit(x, y, kWall, kSpacing).runout_m == Approx(0.1 + 30 * kSpacing).epsilon(1e-12));
  x.push_back(toe - 1.9 * kSpacing), y.push_back(0.0), z.push_back(2 * kSpacing);
  CHECK(soilsph::sph::measure_slab_deposit(x, y, z, kWall, kSpacing).runout_m ==
        Approx(0.1 + 1.9 * kSpacing).epsilon(1e-12));
}

TEST_CASE("a trapezoid: the angle is that of the slope, not of the plateau", "[deposit]") {
  // Plateau of height 3 cm over the 3 cm next to the wall, then a 35° slope down to the toe.
  const double height = 0.03, slope = std::tan(35.0 * std::numbers::pi / 180.0);
  const double shoulder = kWall - 0.03, toe = shoulder - height / slope;
  const int columns = static_cast<int>(std::floor((kWall - toe) / kSpacing)) + 1;
  Particles pile;
  pile.add_profile(columns, [&](double px) { return std::min(height, slope * (px - toe)); });
  const auto m = pile.measure();
  const double leftmost = kWall - (columns - 1) * kSpacing;
  CHECK(m.runout_m == Approx(kWall - leftmost).epsilon(1e-12));
  CHECK(m.height_m == Approx(height).epsilon(1e-12));
  CHECK(m.repose_angle_deg == Approx(35.0).epsilon(1e-9));
}

TEST_CASE("a staircase lattice triangle: the angle within the discretisation bound", "[deposit]") {
  // Particles on the lattice (x, y) = (W − i·dx, j·dx) under the line y = tanθ (x − toe): each strip's
  // top is below the line by less than dx. For errors e ∈ (−dx, 0] over a fitted length L the
  // least-squares slope error is at most dx·Σ|x−x̄| / Σ(x−x̄)² ≈ dx (L/4) / (L²/12) = 3 dx / L,
  // i.e. an angle error below cos²θ · 3 dx / L radians.
  const double angle = 30.0, slope = std::tan(angle * std::numbers::pi / 180.0);
  const double toe = kWall - 100 * kSpacing;
  Particles pile;
  for (int i = 0; i <= 100; ++i) {
    const double px = kWall - i * kSpacing;
    for (int j = 0; j * kSpacing <= slope * (px - toe) + 1e-12; ++j) pile.add(px, j * kSpacing);
  }
  const auto m = pile.measure();
  const double fitted_length = (0.9 - 0.1) * 0.1;
  const double bound =
      degrees(std::pow(std::cos(angle * std::numbers::pi / 180.0), 2) * 3 * kSpacing / fitted_length);
  CHECK(std::abs(m.repose_angle_deg - angle) < bound);
  CHECK(m.runout_m == Approx(0.1).epsilon(1e-12));
  CHECK(m.height_m <= slope * 0.1);
  CHECK(m.height_m > slope * 0.1 - kSpacing);
}

TEST_CASE("invalid input is rejected", "[deposit]") {
  const std::vector<double> empty, one{0.0}, two{0.0, 1.0}, nan{std::nan("")};
  CHECK_THROWS_AS(measure_deposit(empty, empty, kWall, kSpacing), std::invalid_argument);
  CHECK_THROWS_AS(measure_deposit(one, two, kWall, kSpacing), std::invalid_argument);
  CHECK_THROWS_AS(measure_deposit(one, one, kWall, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(measure_deposit(nan, one, kWall, kSpacing), std::invalid_argument);
}

TEST_CASE("runout and height of random clouds agree with a brute-force cluster search", "[deposit]") {
  // Independent check of the cell-grid clustering: breadth-first search over all pairs.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-0.03, kWall), uy(0.0, 0.02);
  const double link = soilsph::sph::deposit_link_spacings * kSpacing;
  int compared = 0;
  for (int cloud = 0; cloud < 40; ++cloud) {
    const std::size_t n = 200 + 20 * cloud;  // sparse to dense: many small clusters to one
    std::vector<double> x(n), y(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = ux(rng), y[i] = uy(rng);
    std::vector<int> label(n, -1);
    std::vector<std::size_t> sizes;
    for (std::size_t seed = 0; seed < n; ++seed) {
      if (label[seed] >= 0) continue;
      const int id = static_cast<int>(sizes.size());
      std::vector<std::size_t> queue{seed};
      label[seed] = id;
      for (std::size_t k = 0; k < queue.size(); ++k) {
        for (std::size_t j = 0; j < n; ++j) {
          if (label[j] < 0 && std::hypot(x[queue[k]] - x[j], y[queue[k]] - y[j]) <= link) {
            label[j] = id;
            queue.push_back(j);
          }
        }
      }
      sizes.push_back(queue.size());
    }
    const auto largest = std::max_element(sizes.begin(), sizes.end());
    if (std::count(sizes.begin(), sizes.end(), *largest) > 1) continue;  // a tie: either is right
    const int id = static_cast<int>(largest - sizes.begin());
    double min_x = 1e300, max_y = -1e300;
    for (std::size_t i = 0; i < n; ++i) {
      if (label[i] != id) continue;
      min_x = std::min(min_x, x[i]);
      max_y = std::max(max_y, y[i]);
    }
    const auto m = measure_deposit(x, y, kWall, kSpacing);
    INFO("cloud " << cloud << " of " << n << " particles, largest cluster " << *largest);
    CHECK(m.runout_m == kWall - min_x);
    CHECK(m.height_m == max_y);
    ++compared;
  }
  CHECK(compared >= 30);
}

TEST_CASE("runout_thick_m: the toe where the deposit reaches the given thickness, ignoring a thin tail",
          "[deposit]") {
  // A 45° slope from height 20 mm at the wall down to the floor at x = W − 20 mm, then a tail one
  // particle thick for another 30 mm. Thickness of a strip = top y + spacing.
  Particles deposit;
  deposit.add_profile(21, [](double px) { return 0.020 - (kWall - px); });  // slope: 20 mm at the wall
  for (int k = 21; k <= 50; ++k) deposit.add(kWall - k * kSpacing, 0.0);    // the thin tail
  const auto tail = measure_deposit(deposit.x, deposit.y, kWall, kSpacing, 0.0);
  CHECK(tail.runout_m == Approx(0.050).epsilon(1e-12));  // the tail counts for runout_m
  CHECK(std::isnan(tail.runout_thick_m));                // not asked for
  // 6 mm thick: top y ≥ 5 mm, on the slope 15 mm from the wall.
  const auto thick = measure_deposit(deposit.x, deposit.y, kWall, kSpacing, 0.006);
  CHECK(thick.runout_thick_m == Approx(0.015).epsilon(1e-9));
  // A threshold of one spacing: the one-particle tail is that thick, so its end counts.
  CHECK(measure_deposit(deposit.x, deposit.y, kWall, kSpacing, kSpacing).runout_thick_m ==
        Approx(0.050).epsilon(1e-12));
}

TEST_CASE("a deposit measured in a mirrored or turned frame gives the column frame's measures", "[deposit][frame]") {
  // A 30° slope of 25 columns against the wall, measured as the column is ([deposit] defaults) ...
  Particles slope;
  const double tan30 = std::tan(std::numbers::pi / 6.0);
  slope.add_profile(25, [&](double px) { return 0.002 + tan30 * (px - (kWall - 24 * kSpacing)); });
  const soilsph::sph::DepositFrame column{{kWall, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, 0.004};
  const auto reference = measure_deposit(slope.x, slope.y, column, kSpacing);
  // ... is the same deposit, to the bit, in the column's frame through the frame overload
  const auto plain = measure_deposit(slope.x, slope.y, kWall, kSpacing, 0.004);
  CHECK(reference.runout_m == plain.runout_m);
  CHECK(reference.height_m == plain.height_m);
  CHECK(reference.repose_angle_deg == plain.repose_angle_deg);
  CHECK(reference.runout_thick_m == plain.runout_thick_m);

  SECTION("mirrored: flowing towards +x from a wall at x = -W, on a floor 0.5 m up") {
    std::vector<double> x(slope.x.size()), y(slope.y.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = -slope.x[i], y[i] = slope.y[i] + 0.5;
    const auto m = measure_deposit(x, y, {{-kWall, 0.5}, {1.0, 0.0}, {0.0, 1.0}, 0.004}, kSpacing);
    CHECK(m.runout_m == Approx(reference.runout_m).epsilon(1e-12));
    CHECK(m.height_m == Approx(reference.height_m).epsilon(1e-9));
    CHECK(m.repose_angle_deg == Approx(reference.repose_angle_deg).epsilon(1e-9));
    CHECK(m.runout_thick_m == Approx(reference.runout_thick_m).epsilon(1e-12));
  }
  SECTION("turned by 40 degrees about the origin with its gravity (an inclined chute's frame)") {
    const double c = std::cos(0.7), s = std::sin(0.7);
    std::vector<double> x(slope.x.size()), y(slope.y.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = c * slope.x[i] - s * slope.y[i], y[i] = s * slope.x[i] + c * slope.y[i];
    const soilsph::sph::DepositFrame turned{{c * kWall, s * kWall}, {-c, -s}, {-s, c}, 0.004};
    const auto m = measure_deposit(x, y, turned, kSpacing);
    CHECK(m.runout_m == Approx(reference.runout_m).epsilon(1e-9));
    CHECK(m.height_m == Approx(reference.height_m).epsilon(1e-9));
    CHECK(m.repose_angle_deg == Approx(reference.repose_angle_deg).epsilon(1e-6));
    CHECK(m.runout_thick_m == Approx(reference.runout_thick_m).epsilon(1e-9));
  }
}
