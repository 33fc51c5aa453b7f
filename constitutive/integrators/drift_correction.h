#pragma once
/// @file
/// Drift correction: brings a stress state that an explicit or extrapolated step left off the yield
/// surface back onto it (Sloan, Abbo & Sheng 2001, §4: the consistent correction
/// σ ← σ − δλ D:n_g, p_c ← p_c(δλ n_g), δλ = f/(n_f:D:n_g + H); the normal correction
/// σ ← σ − f n_f/(n_f:n_f) where that does not reduce |f|; the model's own geometric `correct()` as a
/// last resort). Used after every `substep` substep and after the extrapolated sub-increments of the
/// error-controlled MCC `implicit`.
#include <cmath>

#include "constitutive/elasticity.h"
#include "constitutive/tensor.h"

namespace soilsph {

/// |normalized f| accepted as "on the surface" (Sloan's FTOL).
inline constexpr double kSurfaceTolerance = 1e-9;

namespace drift_detail {
inline constexpr int kMaxIterations = 5;
}  // namespace drift_detail

/// Brings (σ, p_c) of a state that should lie on the surface back to f = 0 (within
/// kSurfaceTolerance); returns the multiplier of the correction and adds its plastic strain.
template <class Model>
double correct_drift(const Model& model, Mat3& sigma, double& pc, Mat3& plastic_strain) {
  double total = 0.0;
  for (int it = 0; it < drift_detail::kMaxIterations; ++it) {
    const double f = model.normalized_yield(sigma, pc);
    if (std::abs(f) <= kSurfaceTolerance) return total;
    const double f_abs = model.yield(sigma, pc);
    const Moduli D = model.elasticity().at(mean_pressure(sigma));
    const Mat3 n_f = model.yield_gradient(sigma, pc);
    const Mat3 n_g = model.flow_direction(sigma, pc);
    const Mat3 D_ng = D.stiffness(n_g);
    const double denominator = ddot(n_f, D_ng) + model.hardening_modulus(sigma, pc);
    if (denominator > 0.0) {
      const double d_lambda = f_abs / denominator;
      const Mat3 trial = sigma - d_lambda * D_ng;
      const double trial_pc = model.harden(pc, d_lambda * n_g);
      // With p_c in the normalisation, compared in absolute terms (Pa²): f normalised by the corrected
      // p_c would call a correction that runs p_c away (1e20 Pa from a 0.26 Pa surface, found by the
      // stress test) an improvement.
      const bool better = Model::kHasPreconsolidation
                              ? std::abs(model.yield(trial, trial_pc)) < std::abs(f_abs)
                              : std::abs(model.normalized_yield(trial, trial_pc)) < std::abs(f);
      if (better) {
        sigma = trial;
        pc = trial_pc;
        plastic_strain += d_lambda * n_g;
        total += d_lambda;
        continue;
      }
    }
    const double nn = ddot(n_f, n_f);
    const Mat3 normal = nn > 0.0 ? Mat3(sigma - f_abs / nn * n_f) : sigma;
    if (!(std::abs(model.normalized_yield(normal, pc)) < std::abs(f))) break;
    sigma = normal;  // the normal correction keeps p_c (Sloan et al. 2001, eq 41)
  }
  if (std::abs(model.normalized_yield(sigma, pc)) > kSurfaceTolerance) sigma = model.correct(sigma, pc);
  return total;
}

}  // namespace soilsph
