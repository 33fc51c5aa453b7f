// The neighbour list in 2D and 3D against a brute-force search: the same pairs, W and ∇W, boundary
// pairs left out; and, with the cell grid anchored at a fixed origin, rows that do not depend on
// which other particles are present (the property a domain decomposition needs).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "sph/neighbours/neighbour_list.h"

using namespace soilsph::sph;

namespace {
/// Points of a lattice of spacing dx, n per axis, each moved by a deterministic offset up to
/// ±jitter dx along each axis (so that distances are not all alike), as coordinate arrays.
template <int dim>
std::array<std::vector<double>, dim> jittered_lattice(int n, double dx, double jitter_ratio = 0.3) {
  std::array<std::vector<double>, dim> x;
  const int nz = dim == 3 ? n : 1;
  unsigned state = 12345u;
  const auto jitter = [&] {  // a linear congruential sequence in [−jitter_ratio, jitter_ratio)
    state = state * 1664525u + 1013904223u;
    return jitter_ratio * (2.0 * (state >> 8) / double(1u << 24) - 1.0);
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int c[3] = {i, j, k};
        for (int d = 0; d < dim; ++d) x[d].push_back((c[d] + jitter()) * dx);
      }
  return x;
}

template <int dim>
Coordinates<dim> view(const std::array<std::vector<double>, dim>& x) {
  Coordinates<dim> c;
  for (int d = 0; d < dim; ++d) c[d] = x[d];
  return c;
}

/// ∇_i W_ij of a row's pair k, from the dW/dr / r it stores.
template <int dim>
std::array<double, dim> gradient(const PairList<dim>& nl, const Coordinates<dim>& x, std::size_t i,
                                 std::size_t k) {
  const auto row = nl.row(i);
  const auto j = static_cast<std::size_t>(row.j[k]);
  std::array<double, dim> g;
  for (int d = 0; d < dim; ++d) g[d] = row.dw_over_r[k] * (x[d][i] - x[d][j]);
  return g;
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("the neighbour list equals a brute-force search", "[neighbours]", ((int dim), dim), 2, 3) {
  const double dx = 1.0e-3;
  const int n = dim == 2 ? 24 : 9;
  const auto points = jittered_lattice<dim>(n, dx);
  const Coordinates<dim> x = view<dim>(points);
  const std::size_t count = x[0].size(), first_boundary = count - count / 5;  // the last fifth: boundary
  const CubicSplineKernel<dim> W(1.3 * dx);
  PairList<dim> nl;
  nl.build(x, W, first_boundary);
  REQUIRE(nl.size() == count);
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < count; ++i) {
    std::map<std::size_t, double> expected;  // j → r, by brute force
    for (std::size_t j = 0; j < count; ++j) {
      if (j == i || (i >= first_boundary && j >= first_boundary)) continue;
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += (x[d][i] - x[d][j]) * (x[d][i] - x[d][j]);
      if (r2 < W.support() * W.support()) expected[j] = std::sqrt(r2);
    }
    const auto row = nl.row(i);
    INFO("particle " << i);
    REQUIRE(row.size == expected.size());
    for (std::size_t k = 0; k < row.size; ++k) {
      const auto j = static_cast<std::size_t>(row.j[k]);
      REQUIRE(expected.count(j) == 1);
      const double r = expected[j];
      CHECK(row.w[k] == Approx(W.value(r)).epsilon(1e-12));
      const auto g = gradient<dim>(nl, x, i, k);
      for (int d = 0; d < dim; ++d)
        CHECK(g[d] == Approx(W.derivative(r) * (x[d][i] - x[d][j]) / r).epsilon(1e-10).margin(1e-6));
    }
    pairs += row.size;
  }
  // A full neighbourhood has ~21 (2D) or ~80 (3D) pairs at h = 1.3 dx: the test sees real rows.
  CHECK(pairs > count * (dim == 2 ? 10 : 30));
}

TEMPLATE_TEST_CASE_SIG("with an anchored grid a particle's row does not depend on the other particles present",
                       "[neighbours]", ((int dim), dim), 2, 3) {
  // The same particles alone, and with more of them far away on both sides (another process's
  // share, or particles that change the bounding box): the same pairs in the same order.
  const double dx = 1.0e-3;
  const auto points = jittered_lattice<dim>(dim == 2 ? 16 : 7, dx);
  auto more = points;
  for (const double far : {-0.01, 0.013})
    for (std::size_t i = 0; i < 5; ++i)
      for (int d = 0; d < dim; ++d) more[d].push_back(points[d][i] + far * (d + 1));
  const CubicSplineKernel<dim> W(1.3 * dx);
  std::array<double, dim> origin;
  origin.fill(-0.0123);
  PairList<dim> alone, among;
  alone.anchor_cells_at(origin);
  among.anchor_cells_at(origin);
  const Coordinates<dim> x = view<dim>(points), y = view<dim>(more);
  alone.build(x, W, x[0].size());
  among.build(y, W, y[0].size());
  for (std::size_t i = 0; i < x[0].size(); ++i) {
    const auto a = alone.row(i), b = among.row(i);
    REQUIRE(a.size == b.size);
    for (std::size_t k = 0; k < a.size; ++k) {
      REQUIRE(a.j[k] == b.j[k]);
      CHECK(a.w[k] == b.w[k]);
    }
  }
}

namespace {
/// The neighbour list's mean bytes per particle on a lattice of `side` points a side disturbed by
/// ±2 % of the spacing, at h = 1.3 Δp.
template <int dim>
std::size_t lattice_list_bytes(int side) {
  const double dx = 1.0e-3;
  const auto points = jittered_lattice<dim>(side, dx, 0.02);
  PairList<dim> nl;
  nl.build(view<dim>(points), CubicSplineKernel<dim>(1.3 * dx), points[0].size());
  return nl.bytes_per_particle();
}
}  // namespace

TEST_CASE("a 3D particle's neighbour list takes under 3 KB", "[neighbours]") {
  // 92 lattice points lie within 2h + s = 2.925 dx; a row holds exactly its candidates, 24 B each
  // (two indices and two doubles), so an interior row takes about 2.2 KB, the rows at the block's
  // faces less.
  CHECK(lattice_list_bytes<3>(8) <= 3000);
}

TEST_CASE("a 2D particle's neighbour list takes under 800 B", "[neighbours]") {
  // 24 lattice points lie within 2h + s = 2.925 dx in the plane; a slot is 24 B (a candidate, j,
  // W and dW/dr / r), so an interior row takes 576 B and its place 44 B. A row that also stored
  // x_i − x_j and ∇_i W_ij (48 B a slot) would take about 1.2 KB.
  CHECK(lattice_list_bytes<2>(30) <= 800);
}

TEST_CASE("a ghost out of the soil's reach holds no pair slots", "[neighbours]") {
  // Ghosts pair only with soil: a floor of ghosts far below the soil has no candidates, so it adds
  // its rows' places (under 64 B each) and nothing else, where one slot is 24 B and a soil row ~90.
  const double dx = 1.0e-3;
  const auto soil = jittered_lattice<3>(6, dx, 0.02);
  auto with_floor = soil;
  const int side = 20;
  for (int k = 0; k < side; ++k)
    for (int i = 0; i < side; ++i) {
      with_floor[0].push_back(i * dx);
      with_floor[1].push_back(-50.0 * dx);
      with_floor[2].push_back(k * dx);
    }
  const CubicSplineKernel<3> kernel(1.3 * dx);
  PairList<3> alone, beside_floor;
  alone.build(view<3>(soil), kernel, soil[0].size());
  beside_floor.build(view<3>(with_floor), kernel, soil[0].size());
  const std::size_t ghosts = side * side;
  CHECK(beside_floor.bytes() - alone.bytes() < 64 * ghosts);
  for (std::size_t g = soil[0].size(); g < with_floor[0].size(); ++g) CHECK(beside_floor.pair_count(g) == 0);
}
