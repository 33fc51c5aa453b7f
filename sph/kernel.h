#pragma once
/// @file
/// The cubic-spline smoothing kernel (paper eq 2–3) in 2D:
///   W(R, h) = a_d { 2/3 − R² + R³/2   (0 ≤ R < 1);  (2 − R)³/6   (1 ≤ R < 2);  0   (R ≥ 2) },
///   R = r/h,  a_d = 15/(7π h²),
/// with compact support 2h. Its radial derivative, by differentiating the two branches:
///   dW/dr = a_d/h { −2R + 3R²/2;  −(2 − R)²/2;  0 }.
/// The gradient ∇_i W_ij = (dW/dr / r)(x_i − x_j) needs dW/dr / r; on the inner branch it is the
/// polynomial a_d/h² (−2 + 3R/2) (R/r = 1/h), so only the outer branch divides by r.
#include <numbers>

namespace soilsph::sph {

class CubicSpline {
 public:
  /// @param h smoothing length (m).
  explicit CubicSpline(double h)
      : h_(h), inv_h_(1.0 / h), a_d_(15.0 / (7.0 * std::numbers::pi * h * h)), a_d_over_6_(a_d_ / 6.0) {}

  double smoothing_length() const { return h_; }
  /// Support radius 2h: W and its gradient vanish beyond it.
  double support() const { return 2.0 * h_; }

  /// W(r, h) and dW/dr / r together, from one branch on R (the pair fill: ∇_i W_ij is the second
  /// times x_i − x_j). One division on the outer branch, none on the inner one; 0 beyond the support.
  struct ValueAndGradientFactor {
    double value, dw_over_r;
  };
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
  double h_;
  double inv_h_;
  double a_d_;
  double a_d_over_6_;
};

}  // namespace soilsph::sph
