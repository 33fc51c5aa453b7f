#pragma once
/// @file
/// f^n with f = W / W(Δp), the artificial stress's weight (stages/artificial_stress.h), from a table
/// instead of `std::pow`, which was 11 % of the MCC collapse's step (perf, 1 mm, one thread).
///
/// 0 ≤ W ≤ W(0) for every pair, so f^n is tabulated once on a uniform grid of W over [0, W(0)] with
/// its derivative, and evaluated by cubic Hermite interpolation. On an interval of width Δ (in f)
/// its error is at most Δ⁴/384 · max |n(n−1)(n−2)(n−3) f^(n−4)| (e.g. Süli & Mayers, An
/// Introduction to Numerical Analysis, 2003, Thm 6.4). For n = 2.55, h = 1.3Δp and 1024 intervals:
/// below 6e-10 relative wherever f ≥ 0.1 and 2e-9 absolute in the first interval, where the bound
/// does not hold (f^n is not four times differentiable at 0), against f ≈ 1 at the nearest
/// neighbours (tests/sph/test_stages.cpp). n ≥ 1 (scene.cpp): below it the slope at f = 0 is infinite.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace soilsph::sph {

class KernelRatioPower {
 public:
  /// @param exponent n ≥ 1; @param w_at_spacing W(Δp) > 0; @param w_at_zero W(0) ≥ W(Δp), the
  /// kernel's largest value; @param intervals the grid's intervals.
  KernelRatioPower(double exponent, double w_at_spacing, double w_at_zero, std::size_t intervals = 1024)
      : step_(w_at_zero / static_cast<double>(intervals)), inv_step_(1.0 / step_), nodes_(intervals + 1) {
    for (std::size_t k = 0; k <= intervals; ++k) {
      const double f = static_cast<double>(k) * step_ / w_at_spacing;
      // d(f^n)/dW = n f^(n−1) / W(Δp); stored times the step, the form the Hermite basis takes.
      nodes_[k] = {std::pow(f, exponent), exponent * std::pow(f, exponent - 1.0) * step_ / w_at_spacing};
    }
  }

  /// (w / W(Δp))^n for 0 ≤ w ≤ W(0).
  double operator()(double w) const {
    const double t = w * inv_step_;
    const std::size_t k = std::min(static_cast<std::size_t>(t), nodes_.size() - 2);
    const double s = t - static_cast<double>(k), r = 1.0 - s;
    const Node& a = nodes_[k];
    const Node& b = nodes_[k + 1];
    // Hermite basis: (1 + 2s) r², s r², s² (3 − 2s), −s² r.
    return r * r * ((1.0 + 2.0 * s) * a.value + s * a.slope) +
           s * s * ((3.0 - 2.0 * s) * b.value - r * b.slope);
  }

 private:
  struct Node {
    double value, slope;
  };
  double step_, inv_step_;
  std::vector<Node> nodes_;
};

}  // namespace soilsph::sph
