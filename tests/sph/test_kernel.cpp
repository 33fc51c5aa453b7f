// The cubic-spline kernel (eq 2-3): normalisation, derivative, and its lattice sums for h/dx = 1.3.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "../common/lattice_sums.h"
#include "sph/kernel.h"

using namespace soilsph::sph;

TEST_CASE("the cubic spline integrates to one over the plane", "[kernel]") {
  // ∫ W dA = ∫_0^{2h} W(r) 2πr dr, by the composite Simpson rule (exact for the piecewise cubic
  // times r on each branch when the knot r = h is a node).
  const double h = 1.7e-3;
  const CubicSpline W(h);
  const int n = 2000;  // intervals on [0, 2h], even, with r = h a node
  const double dr = 2.0 * h / n;
  double integral = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double r = k * dr;
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    integral += weight * W.value(r) * 2.0 * std::numbers::pi * r;
  }
  integral *= dr / 3.0;
  CHECK(integral == Approx(1.0).epsilon(1e-10));
  CHECK(W.value(2.0 * h) == 0.0);
  CHECK(W.value(3.0 * h) == 0.0);
  CHECK(W.value(0.0) == Approx(15.0 / (7.0 * std::numbers::pi * h * h) * 2.0 / 3.0));
}

TEST_CASE("the kernel derivative matches central differences", "[kernel]") {
  const double h = 1.0e-3;
  const CubicSpline W(h);
  for (const double R : {0.1, 0.5, 0.9, 1.2, 1.5, 1.9}) {
    const double r = R * h, e = 1e-7 * h;
    const double numeric = (W.value(r + e) - W.value(r - e)) / (2.0 * e);
    CHECK(W.derivative(r) == Approx(numeric).epsilon(1e-6));
  }
}

TEST_CASE("the pair fill's W and dW/dr / r match the kernel and central differences over r", "[kernel]") {
  // value_and_gradient_factor takes dW/dr / r on the inner branch as a polynomial without dividing
  // by r (kernel.h): W must be eq 2, dW/dr / r the numeric derivative divided by r on both branches,
  // −2 a_d/h² at r → 0, and both vanish beyond the support.
  const double h = 1.3e-3, a_d = 15.0 / (7.0 * std::numbers::pi * h * h);
  const CubicSpline W(h);
  for (const double R : {1e-6, 0.1, 0.5, 0.9, 0.999, 1.001, 1.2, 1.5, 1.9, 1.999}) {
    const double r = R * h, e = 1e-7 * h;
    const auto [value, dw_over_r] = W.value_and_gradient_factor(r);
    INFO("R = " << R);
    const double W_eq2 = a_d * (R < 1.0 ? 2.0 / 3.0 - R * R + 0.5 * R * R * R : std::pow(2.0 - R, 3) / 6.0);
    CHECK(value == Approx(W_eq2).epsilon(1e-10));  // 2 − R cancels near the support's edge (R = 1.999: ~1e-12)
    if (R > 1e-3) {
      const double numeric = (W.value(r + e) - W.value(r - e)) / (2.0 * e);
      CHECK(dw_over_r == Approx(numeric / r).epsilon(1e-6));
    } else {
      CHECK(dw_over_r == Approx(-2.0 * a_d / (h * h)).epsilon(1e-5));
    }
  }
  CHECK(W.value_and_gradient_factor(2.0 * h).dw_over_r == 0.0);
  CHECK(W.value_and_gradient_factor(2.5 * h).value == 0.0);
}

TEST_CASE("on a lattice the kernel sums to one and its gradient to zero", "[kernel]") {
  // Σ_j V_j W_ij and Σ_j V_j ∇W_ij at a particle with a full neighbourhood, V = dx².
  const double dx = 1.0e-3;
  for (const double ratio : {1.2, 1.3, 1.5}) {
    const CubicSpline W(ratio * dx);
    double sum = 0.0, gx = 0.0, gy = 0.0;
    for (int a = -4; a <= 4; ++a)
      for (int b = -4; b <= 4; ++b) {
        const double rx = -a * dx, ry = -b * dx, r = std::hypot(rx, ry);  // x_i − x_j, i at the origin
        sum += dx * dx * W.value(r);
        if (r > 0.0) gx += dx * dx * W.derivative(r) * rx / r, gy += dx * dx * W.derivative(r) * ry / r;
      }
    INFO("h/dx = " << ratio);
    CHECK(sum == Approx(1.0).epsilon(5e-3));  // quadrature error of the lattice sum
    CHECK(std::abs(gx) < 1e-9 / dx);          // zero by symmetry, to round-off (scale 1/dx)
    CHECK(std::abs(gy) < 1e-9 / dx);
  }
}

namespace {
/// ∫ W dV over the plane (2D: 2πr dr) or space (3D: 4πr² dr), by the composite Simpson rule with
/// r = h a node (exact for the piecewise polynomials of both kernels up to round-off).
template <class Kernel>
double radial_integral(const Kernel& W) {
  const double h = W.smoothing_length();
  const int n = 2000;
  const double dr = 2.0 * h / n;
  double integral = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double r = k * dr;
    const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    const double shell = Kernel::dimension == 2 ? 2.0 * std::numbers::pi * r : 4.0 * std::numbers::pi * r * r;
    integral += weight * W.value(r) * shell;
  }
  return integral * dr / 3.0;
}

}  // namespace

TEMPLATE_TEST_CASE("both kernels integrate to one in 2D and 3D", "[kernel]", CubicSplineKernel<2>,
                   CubicSplineKernel<3>, WendlandC2Kernel<2>, WendlandC2Kernel<3>) {
  const TestType W(1.7e-3);
  CHECK(radial_integral(W) == Approx(1.0).epsilon(1e-10));
  CHECK(W.value(2.0 * W.smoothing_length()) == 0.0);
  CHECK(W.value_and_gradient_factor(2.5 * W.smoothing_length()).dw_over_r == 0.0);
}

TEST_CASE("the 3D normalisations are 3/(2 pi h^3) and 21/(16 pi h^3)", "[kernel]") {
  // W(0): the cubic spline's bracket is 2/3 there, Wendland's (1 − 0)⁴ (0 + 1) = 1.
  const double h = 1.3e-3, pi = std::numbers::pi;
  CHECK(CubicSplineKernel<3>(h).value(0.0) == Approx(3.0 / (2.0 * pi * h * h * h) * 2.0 / 3.0));
  CHECK(WendlandC2Kernel<3>(h).value(0.0) == Approx(21.0 / (16.0 * pi * h * h * h)));
  CHECK(WendlandC2Kernel<2>(h).value(0.0) == Approx(7.0 / (4.0 * pi * h * h)));
}

TEMPLATE_TEST_CASE("dW/dr / r of both kernels matches central differences in 2D and 3D", "[kernel]",
                   CubicSplineKernel<2>, CubicSplineKernel<3>, WendlandC2Kernel<2>, WendlandC2Kernel<3>) {
  const double h = 1.1e-3;
  const TestType W(h);
  for (const double R : {0.1, 0.5, 0.9, 1.2, 1.5, 1.9}) {
    const double r = R * h, e = 1e-7 * h;
    const double numeric = (W.value(r + e) - W.value(r - e)) / (2.0 * e);
    INFO("R = " << R);
    CHECK(W.value_and_gradient_factor(r).dw_over_r == Approx(numeric / r).epsilon(1e-6));
  }
}

TEMPLATE_TEST_CASE("on a 3D lattice the kernels sum to one and the gradient's moment is minus the identity",
                   "[kernel]", CubicSplineKernel<3>, WendlandC2Kernel<3>) {
  const double dx = 1.0e-3;
  for (const double ratio : {1.2, 1.3, 1.5}) {
    const TestType W(ratio * dx);
    const soilsph::test::LatticeSums s = soilsph::test::lattice_sums(W, dx);
    INFO("h/dx = " << ratio);
    // The lattice sums' quadrature error: up to 2 % at h/dx = 1.2 (Wendland, the wider kernel).
    CHECK(s.sum == Approx(1.0).epsilon(2.5e-2));
    for (int p = 0; p < 3; ++p) {
      CHECK(std::abs(s.gradient[p]) < 1e-9 / dx);  // zero by symmetry
      for (int q = 0; q < 3; ++q) {
        INFO("moment " << p << q);
        if (p == q)
          CHECK(s.moment[p][q] == Approx(-1.0).epsilon(2.5e-2));
        else
          CHECK(std::abs(s.moment[p][q]) < 1e-12);
      }
    }
  }
}
