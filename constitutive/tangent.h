#pragma once
/// @file
/// The algorithmic tangent ∂σ_{n+1}/∂Δε of one update, as a 6×6 Voigt matrix (voigt.h). Used by
/// the mixed-control driver's Newton iteration. Models that provide an analytic consistent
/// tangent (`consistent_tangent(state, strain_increment)`) use it; otherwise central differences
/// of the update are taken.
#include "constitutive/integrators/integrator.h"
#include "constitutive/models/dilatancy_cutoff.h"
#include "constitutive/state.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// Central-difference tangent of `model.update` with respect to the strain increment.
/// The step is relative to the increment's size, with an absolute floor.
template <class Model>
Mat6 finite_difference_tangent(const Model& model, const State& state, const Mat3& strain_increment) {
  const Vec6 base = strain_to_voigt(strain_increment);
  const double h = std::max(1e-7 * base.norm(), 1e-10);
  Mat6 tangent;
  for (int k = 0; k < 6; ++k) {
    Vec6 plus = base, minus = base;
    plus(k) += h;
    minus(k) -= h;
    const Mat3 s_plus = model.update(state, strain_from_voigt(plus), Mat3::Zero()).stress;
    const Mat3 s_minus = model.update(state, strain_from_voigt(minus), Mat3::Zero()).stress;
    tangent.col(k) = (stress_to_voigt(s_plus) - stress_to_voigt(s_minus)) / (2.0 * h);
  }
  return tangent;
}

/// For a model whose `implicit_update` writes its consistent tangent (D-P, MC): that tangent, of the
/// model that flows at the state's plastic dilation (models/dilatancy_cutoff.h), for `implicit` and
/// `substep` (each model says why it serves substep); central differences for `explicit`, whose
/// update is another map. Instantiated in the model's source, where its implicit_update is declared.
template <class Model>
Mat6 return_tangent_or_differences(const Model& model, const State& state, const Mat3& strain_increment) {
  if (model.integrator() == Integrator::Explicit) return finite_difference_tangent(model, state, strain_increment);
  Mat6 tangent;
  implicit_update(flowing_model(model, state.plastic_dilation), state, strain_increment, &tangent);
  return tangent;
}

/// The tangent of one update: the model's consistent tangent where it has one, else differences.
template <class Model>
Mat6 algorithmic_tangent(const Model& model, const State& state, const Mat3& strain_increment) {
  if constexpr (requires { model.consistent_tangent(state, strain_increment); }) {
    return model.consistent_tangent(state, strain_increment);
  } else {
    return finite_difference_tangent(model, state, strain_increment);
  }
}

}  // namespace soilsph
