#pragma once
/// @file
/// The coordinates the optimiser moves: each parameter x in (lower, upper) as an unbounded z.
/// First u = ln x when the bounds are positive (so a factor weighs alike at 0.01 and at 100; the
/// "logarithms for positive ones"), else u = x; then the logistic map
///
///     u = u_lo + (u_hi − u_lo) / (1 + e^(−z)),   z = ln((u − u_lo) / (u_hi − u)),
///
/// keeps every trial inside the bounds while the least-squares problem stays smooth in z. Clamping
/// would be the alternative; it puts kinks and flat, zero-gradient regions into the residuals, where
/// a trust-region method stalls, whereas the logistic map's only cost is that a parameter that
/// belongs on its bound is approached slowly (dx/dz → 0 there; the fit then says so).
#include <cmath>

#include "verification/calibration/calibration_file.h"

namespace soilsph::calibration {

class ParameterScaling {
 public:
  explicit ParameterScaling(const FitParameter& p)
      : logarithmic_(p.lower > 0.0), lo_(inner(p.lower)), hi_(inner(p.upper)) {}

  double to_scaled(double x) const {
    const double u = inner(x);
    return std::log((u - lo_) / (hi_ - u));
  }
  double to_physical(double z) const { return outer(lo_ + (hi_ - lo_) * sigmoid(z)); }
  /// dx/dz by the chain rule: dx/du · du/dz, du/dz = (u_hi − u_lo) s (1 − s) with s the logistic.
  double derivative(double z) const {
    const double s = sigmoid(z);
    const double du_dz = (hi_ - lo_) * s * (1.0 - s);
    return (logarithmic_ ? to_physical(z) : 1.0) * du_dz;
  }
  bool logarithmic() const { return logarithmic_; }

 private:
  static double sigmoid(double z) {
    return z >= 0.0 ? 1.0 / (1.0 + std::exp(-z)) : std::exp(z) / (1.0 + std::exp(z));
  }
  double inner(double x) const { return logarithmic_ ? std::log(x) : x; }
  double outer(double u) const { return logarithmic_ ? std::exp(u) : u; }

  bool logarithmic_;
  double lo_, hi_;
};

}  // namespace soilsph::calibration
