// The SPH velocity gradient (eq 23) and its optional kernel-gradient correction on linear fields.
#include <catch2/catch.hpp>

#include <cmath>

#include "helpers.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/stages/velocity_gradient.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
// A general (non-symmetric) gradient: stretching, shear and spin at once.
constexpr double A[2][2] = {{0.7, -1.3}, {2.1, -0.4}};

Particles linear_field(int n, double dx) {
  Particles p = test::lattice(n, dx, 2000.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.vx[i] = 0.3 + A[0][0] * p.x[i] + A[0][1] * p.y[i];
    p.vy[i] = -0.2 + A[1][0] * p.x[i] + A[1][1] * p.y[i];
  }
  return p;
}

/// The lattice kernel moment m = Σ_j V (x_j − x_i) dW/dx_i for a full neighbourhood, from the kernel
/// formula directly (the diagonal of M; the off-diagonal vanishes by symmetry).
double lattice_moment(const CubicSpline& W, double dx) {
  double m = 0.0;
  for (int a = -4; a <= 4; ++a)
    for (int b = -4; b <= 4; ++b) {
      const double xj = a * dx, r = std::hypot(a * dx, b * dx);
      if (r > 0.0) m += dx * dx * xj * W.derivative(r) * (-xj) / r;
    }
  return m;
}
}  // namespace

TEST_CASE("eq 23 gives the linear field's gradient times the lattice moment in the interior",
          "[velocity-gradient]") {
  const double dx = 1.0e-3;
  const CubicSpline W(1.3 * dx);
  Particles p = linear_field(15, dx);
  NeighbourList nl;
  nl.build(p.x, p.y, W);
  compute_velocity_gradient(p, nl);
  const double m = lattice_moment(W, dx);
  CHECK(m == Approx(1.0).epsilon(0.02));  // eq 23 is exact to the lattice quadrature, ~1 %
  int interior = 0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const bool inside = p.x[i] > 3.5 * dx && p.x[i] < 10.5 * dx && p.y[i] > 3.5 * dx && p.y[i] < 10.5 * dx;
    if (!inside) continue;
    ++interior;
    CHECK(p.lxx[i] == Approx(A[0][0] * m).epsilon(1e-10));
    CHECK(p.lxy[i] == Approx(A[0][1] * m).epsilon(1e-10));
    CHECK(p.lyx[i] == Approx(A[1][0] * m).epsilon(1e-10));
    CHECK(p.lyy[i] == Approx(A[1][1] * m).epsilon(1e-10));
  }
  CHECK(interior == 49);
  // Strain and spin increments over dt split the gradient: Δε_xy = ½(A_xy + A_yx) dt,
  // Δω_xy = ½(A_xy − A_yx) dt.
  const std::size_t centre = 7 * 15 + 7;
  const double dt = 2e-3;
  const VelocityGradient L = stored_velocity_gradient(p, centre);
  CHECK(L.strain_increment(dt)(0, 1) == Approx(0.5 * (A[0][1] + A[1][0]) * m * dt));
  CHECK(L.spin_increment(dt)(0, 1) == Approx(0.5 * (A[0][1] - A[1][0]) * m * dt));
  CHECK(L.spin_increment(dt)(1, 0) == Approx(-0.5 * (A[0][1] - A[1][0]) * m * dt));
  CHECK(L.strain_increment(dt)(2, 2) == 0.0);
}

TEST_CASE("the corrected gradient is exact for a linear field everywhere, edges included",
          "[velocity-gradient]") {
  const double dx = 2.0e-3;
  Particles p = linear_field(9, dx);
  NeighbourList nl;
  nl.build(p.x, p.y, CubicSpline(1.3 * dx));
  compute_velocity_gradient(p, nl, true);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    CHECK(p.lxx[i] == Approx(A[0][0]).margin(1e-9));
    CHECK(p.lxy[i] == Approx(A[0][1]).margin(1e-9));
    CHECK(p.lyx[i] == Approx(A[1][0]).margin(1e-9));
    CHECK(p.lyy[i] == Approx(A[1][1]).margin(1e-9));
  }
}

TEST_CASE("the neighbour list finds exactly the pairs within the support", "[neighbours]") {
  const double dx = 1.0e-3;
  const CubicSpline W(1.3 * dx);
  Particles p = test::lattice(12, dx, 1000.0);
  NeighbourList nl;
  nl.build(p.x, p.y, W);
  for (std::size_t i = 0; i < p.size(); i += 7) {
    std::size_t brute = 0;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i && std::hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]) < W.support()) ++brute;
    CHECK(nl.pair_count(i) == brute);
  }
}

TEST_CASE("the Verlet skin: no new search for small moves, and the pairs stay exact", "[neighbours]") {
  const double dx = 1.0e-3;
  const CubicSpline W(1.3 * dx);
  Particles p = test::lattice(12, dx, 1000.0);
  NeighbourList nl;
  const auto matches_brute_force = [&] {
    for (std::size_t i = 0; i < p.size(); ++i) {
      std::size_t brute = 0;
      for (std::size_t j = 0; j < p.size(); ++j)
        if (j != i && std::hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]) < W.support()) ++brute;
      if (nl.pair_count(i) != brute) return false;
    }
    return true;
  };
  nl.build(p.x, p.y, W);
  CHECK(nl.searches() == 1);
  // Every particle moves by just under s/2 in alternating directions: pairs change, no new search.
  const double small = 0.49 * NeighbourList::kSkinRatio * W.smoothing_length();
  for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += (i % 2 ? small : -small);
  nl.build(p.x, p.y, W);
  CHECK(nl.searches() == 1);
  CHECK(matches_brute_force());
  // One particle beyond s/2: a new search.
  p.y[5] += 0.6 * NeighbourList::kSkinRatio * W.smoothing_length();
  nl.build(p.x, p.y, W);
  CHECK(nl.searches() == 2);
  CHECK(matches_brute_force());
}
