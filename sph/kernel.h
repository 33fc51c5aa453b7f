#pragma once
/// @file
/// The smoothing kernels, for 2 and 3 dimensions, with compact support 2h.
///
/// The cubic spline (paper eq 2–3):
///   W(R, h) = a_d { 2/3 − R² + R³/2   (0 ≤ R < 1);  (2 − R)³/6   (1 ≤ R < 2);  0   (R ≥ 2) },
///   R = r/h,  a_d = 15/(7π h²) in 2D,  3/(2π h³) in 3D
/// (Monaghan's M4 spline 10/(7π h²), 1/(π h³) times (1 − 3R²/2 + 3R³/4) is the same function: the
/// bracket here is 2/3 of his, so a_d is 3/2 of his normalisation; Monaghan 1992, Annu. Rev. Astron.
/// Astrophys. 30, eq 2.6). Its radial derivative, by differentiating the two branches:
///   dW/dr = a_d/h { −2R + 3R²/2;  −(2 − R)²/2;  0 }.
/// The gradient ∇_i W_ij = (dW/dr / r)(x_i − x_j) needs dW/dr / r; on the inner branch it is the
/// polynomial a_d/h² (−2 + 3R/2) (R/r = 1/h), so only the outer branch divides by r.
///
/// The Wendland C2 kernel (Wendland 1995, Adv. Comput. Math. 4; normalisations from Dehnen & Aly
/// 2012, MNRAS 425, table 1, with their support H = 2h):
///   W(R, h) = a_d (1 − R/2)⁴ (2R + 1)   (0 ≤ R < 2),  a_d = 7/(4π h²) in 2D,  21/(16π h³) in 3D,
///   dW/dr = a_d/h · (−5R)(1 − R/2)³,  so  dW/dr / r = −5 a_d/h² (1 − R/2)³ (no division).
/// Both integrate to one over the plane (2D) or space (3D); tests/sph/test_kernel.cpp checks it.
///
/// A scene chooses one ([numerics] kernel, SmoothingKernel below); the cubic spline is the paper's.
/// The Wendland C2 kernel has a non-negative Fourier transform, so it is free of the pairing
/// instability the cubic spline shows at large neighbour numbers (Dehnen & Aly 2012, MNRAS 425).
#include <numbers>

namespace soilsph::sph {

/// W(r, h) and dW/dr / r of one pair, from one branch on R (the pair fill: ∇_i W_ij is the second
/// times x_i − x_j).
struct ValueAndGradientFactor {
  double value, dw_over_r;
};

template <int dim>
  requires(dim == 2 || dim == 3)
class CubicSplineKernel {
 public:
  static constexpr int dimension = dim;

  /// @param h smoothing length (m).
  explicit CubicSplineKernel(double h) : h_(h), inv_h_(1.0 / h), a_d_(normalisation(h)), a_d_over_6_(a_d_ / 6.0) {}

  double smoothing_length() const { return h_; }
  /// Support radius 2h: W and its gradient vanish beyond it.
  double support() const { return 2.0 * h_; }

  /// W(r, h) and dW/dr / r together. One division on the outer branch, none on the inner one; 0
  /// beyond the support.
  using ValueAndGradientFactor = sph::ValueAndGradientFactor;
  ValueAndGradientFactor value_and_gradient_factor(double r) const {
    const double R = r * inv_h_;
    if (R < 1.0) return {a_d_ * (2.0 / 3.0 - R * R + 0.5 * R * R * R), a_d_ * inv_h_ * inv_h_ * (-2.0 + 1.5 * R)};
    if (R < 2.0) {
      const double s = 2.0 - R;
      return {a_d_over_6_ * s * s * s, -0.5 * a_d_ * inv_h_ * s * s / r};
    }
    return {0.0, 0.0};
  }

  /// W(r, h), eq 2.
  double value(double r) const { return value_and_gradient_factor(r).value; }

  /// dW/dr; the gradient with respect to x_i is dW/dr · (x_i − x_j)/r.
  double derivative(double r) const { return value_and_gradient_factor(r).dw_over_r * r; }

 private:
  static double normalisation(double h) {
    if constexpr (dim == 2)
      return 15.0 / (7.0 * std::numbers::pi * h * h);
    else
      return 3.0 / (2.0 * std::numbers::pi * h * h * h);
  }
  double h_;
  double inv_h_;
  double a_d_;
  double a_d_over_6_;
};

/// The kernel of the plane-strain solver.
using CubicSpline = CubicSplineKernel<2>;

template <int dim>
  requires(dim == 2 || dim == 3)
class WendlandC2Kernel {
 public:
  static constexpr int dimension = dim;

  explicit WendlandC2Kernel(double h) : h_(h), inv_h_(1.0 / h), a_d_(normalisation(h)) {}

  double smoothing_length() const { return h_; }
  double support() const { return 2.0 * h_; }

  ValueAndGradientFactor value_and_gradient_factor(double r) const {
    const double R = r * inv_h_;
    if (R >= 2.0) return {0.0, 0.0};
    const double s = 1.0 - 0.5 * R, s3 = s * s * s;
    return {a_d_ * s3 * s * (2.0 * R + 1.0), -5.0 * a_d_ * inv_h_ * inv_h_ * s3};
  }
  double value(double r) const { return value_and_gradient_factor(r).value; }
  double derivative(double r) const { return value_and_gradient_factor(r).dw_over_r * r; }

 private:
  static double normalisation(double h) {
    if constexpr (dim == 2)
      return 7.0 / (4.0 * std::numbers::pi * h * h);
    else
      return 21.0 / (16.0 * std::numbers::pi * h * h * h);
  }
  double h_;
  double inv_h_;
  double a_d_;
};

/// The kernel shapes a scene may choose.
enum class KernelShape { CubicSpline, WendlandC2 };

/// The kernel a scene chose, of either shape. A pass over the pairs asks visit(f), which calls f
/// with the concrete kernel, so that the shape is chosen once, outside the loop over particles, and
/// the pair loop is compiled for it (neighbours/neighbour_list.h, solver.h); value() serves the
/// set-up and the measures, which evaluate W a few times, not per pair and step.
template <int dim>
  requires(dim == 2 || dim == 3)
class SmoothingKernel {
 public:
  SmoothingKernel(KernelShape shape, double h) : shape_(shape), cubic_spline_(h), wendland_(h) {}
  /// A kernel of one shape, so that tests and tools may pass a concrete kernel where the solver's
  /// parts take the scene's.
  SmoothingKernel(const CubicSplineKernel<dim>& k)
      : SmoothingKernel(KernelShape::CubicSpline, k.smoothing_length()) {}
  SmoothingKernel(const WendlandC2Kernel<dim>& k)
      : SmoothingKernel(KernelShape::WendlandC2, k.smoothing_length()) {}

  KernelShape shape() const { return shape_; }
  double smoothing_length() const { return cubic_spline_.smoothing_length(); }
  double support() const { return cubic_spline_.support(); }

  /// f(kernel) with the concrete kernel of the chosen shape.
  template <class F>
  decltype(auto) visit(F&& f) const {
    if (shape_ == KernelShape::WendlandC2) return f(wendland_);
    return f(cubic_spline_);
  }
  double value(double r) const {
    return visit([r](const auto& w) { return w.value(r); });
  }

 private:
  KernelShape shape_;
  CubicSplineKernel<dim> cubic_spline_;
  WendlandC2Kernel<dim> wendland_;
};

}  // namespace soilsph::sph
