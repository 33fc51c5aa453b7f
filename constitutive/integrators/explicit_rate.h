#pragma once
/// @file
/// `explicit`: the paper's scheme. One forward-Euler step of the elastic–plastic rate form with the
/// stress at the start of the increment, then the paper's stress correction:
///   Δλ = n_f : D : Δε / (n_f : D : n_g + H)      (eq 22 for D-P, eq 29 for MCC)
///   Δσ = D : (Δε − Δλ n_g)                        (eq 16, 21, 28)
///   σ ← correct(σ + Δσ)                           (eq 30–33 for D-P, eq 34–35 for MCC)
/// The paper states the plastic branch for states on the surface (f = 0, λ̇ > 0). Forward Euler with
/// hardening leaves the state slightly inside the surface after each plastic step (p lags p_c), so a
/// test on f(σ_n) would alternate plastic and elastic steps along a hardening path. The branch is
/// therefore decided by the elastic trial: plastic when σ_n + D:Δε lies outside the surface and the
/// increment loads it (Δλ > 0), with gradients at σ_n. First order: the drift that the correction
/// removes is what `substep` and `implicit` avoid.
#include "constitutive/state.h"

namespace soilsph {

/// Works for any model that provides elasticity(), normalized_yield(), yield_gradient(),
/// flow_direction(), hardening_modulus(), harden() and correct().
template <class Model>
State explicit_update(const Model& model, const State& start, const Mat3& strain_increment) {
  const Mat3& sigma = start.stress;
  const Moduli D = model.elasticity().at(mean_pressure(sigma));
  const Mat3 elastic_stress_increment = D.stiffness(strain_increment);

  double d_lambda = 0.0;
  Mat3 plastic_flow = Mat3::Zero();
  if (model.yield(sigma + elastic_stress_increment, start.pc) > 0.0) {
    const Mat3 n_f = model.yield_gradient(sigma, start.pc);
    const Mat3 n_g = model.flow_direction(sigma, start.pc);
    const double numerator = ddot(n_f, elastic_stress_increment);
    const double denominator = ddot(n_f, D.stiffness(n_g)) + model.hardening_modulus(sigma, start.pc);
    if (numerator > 0.0 && denominator > 0.0) {
      d_lambda = numerator / denominator;
      plastic_flow = d_lambda * n_g;
    }
  }

  State next = start;
  next.pc = model.harden(start.pc, plastic_flow);
  next.stress = model.correct(sigma + elastic_stress_increment - D.stiffness(plastic_flow), next.pc);
  // All strain the elastic law does not explain is plastic, including the correction's share.
  accumulate_plastic_strain(next, strain_increment - D.compliance(next.stress - sigma));
  next.plastic_multiplier = d_lambda;
  return next;
}

}  // namespace soilsph
