#pragma once
/// @file
/// One update of a model with a dilatancy cut-off (models/dilatancy_cutoff.h), by any integrator:
/// the plastic dilation is counted, and an increment that carries it past the cut-off is split where
/// it reaches it, the first part integrated with ψ and the rest with the ψ = 0 twin.
///
/// The plastic volumetric strain of a part is what the elastic law does not explain,
/// tr Δε − Δ(tr σ)/(3K) (constant K, as D-P and MC have; the rotation by the spin keeps tr σ), so it
/// includes an apex return's opening: a grain that has come apart has no dilatancy left.
/// The split point r ∈ (0, 1), where the dilation after the part rΔε equals the cut-off, is found by
/// the Illinois variant of regula falsi on [0, 1] (the dilation is continuous and non-decreasing in
/// r: 0 until the trial reaches the surface, then growing with the flow); the spin is split in the
/// same ratio. This happens once in a point's history, so its cost does not matter.
#include <cmath>
#include <stdexcept>

#include "constitutive/integrators/integrator.h"
#include "constitutive/state.h"

namespace soilsph {

/// `once(model, state, Δε, Δω)` is one update by the model's scheme.
template <class Model, class Once>
State integrate_across_dilatancy_cutoff(const Model& model, const State& start, const Mat3& strain_increment,
                                        const Mat3& spin_increment, Once once) {
  constexpr int kMaxIterations = 200;
  constexpr double kTolerance = 1e-12;  ///< |dilation − cut-off| relative to the cut-off at the split
  const double bulk3 = 3.0 * model.elasticity().at(0.0).K;
  const double cutoff = model.dilatancy_cutoff();
  // The part [r0, r1] of the increment from `from`, by model m.
  const auto part = [&](const Model& m, const State& from, double r0, double r1) {
    const double r = r1 - r0;
    State next = once(m, from, r * strain_increment, r * spin_increment);
    next.plastic_dilation =
        from.plastic_dilation + r * strain_increment.trace() - (next.stress.trace() - from.stress.trace()) / bulk3;
    return next;
  };
  if (start.plastic_dilation >= cutoff) return part(model.non_dilating(), start, 0.0, 1.0);
  const State whole = part(model, start, 0.0, 1.0);
  // Not past the cut-off, or not finite (a runaway trial of a driver's Newton): the caller judges it.
  if (!(whole.plastic_dilation > cutoff) || !std::isfinite(whole.plastic_dilation)) return whole;

  double lo = 0.0, hi = 1.0, g_lo = start.plastic_dilation - cutoff, g_hi = whole.plastic_dilation - cutoff;
  double r = 1.0;
  State split = whole;
  int kept_side = 0;  // the end kept by the last two steps (Illinois halves its value)
  for (int it = 0;; ++it) {
    if (it == kMaxIterations) throw IntegrationError("dilatancy cut-off: the split point did not converge");
    r = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    split = part(model, start, 0.0, r);
    const double g = split.plastic_dilation - cutoff;
    if (!std::isfinite(g)) throw IntegrationError("dilatancy cut-off: a part of the increment is not finite");
    if (std::abs(g) <= kTolerance * cutoff || hi - lo <= kTolerance) break;
    if (g > 0.0) {
      hi = r, g_hi = g;
      if (kept_side == -1) g_lo *= 0.5;
      kept_side = -1;
    } else {
      lo = r, g_lo = g;
      if (kept_side == 1) g_hi *= 0.5;
      kept_side = 1;
    }
  }
  split.plastic_dilation = cutoff;  // the root's residual (≤ 1e-12 of it) dropped: the twin starts on it
  State end = part(model.non_dilating(), split, r, 1.0);
  end.plastic_multiplier += split.plastic_multiplier;
  return end;
}

}  // namespace soilsph
