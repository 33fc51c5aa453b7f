#pragma once
/// @file
/// `explicit`: the paper's scheme. One forward-Euler step of the elastic–plastic rate form with the
/// stress at the start of the increment, then the paper's stress correction:
///   Δλ = (f_n + n_f : D : Δε) / (n_f : D : n_g + H)   (eq 22 for D-P, eq 29 for MCC, when f_n = 0)
///   Δσ = D : (Δε − Δλ n_g)                        (eq 16, 21, 28)
///   σ ← correct(σ + Δσ)                           (eq 30–33 for D-P, eq 34–35 for MCC)
/// The paper states the plastic branch for states on the surface (f = 0, λ̇ > 0). Forward Euler with
/// hardening leaves the state slightly inside the surface after each plastic step (p lags p_c), so a
/// test on f(σ_n) would alternate plastic and elastic steps along a hardening path. The branch is
/// therefore decided by the elastic trial: plastic when σ_n + D:Δε lies outside the surface and the
/// increment loads it (Δλ > 0), with gradients at σ_n.
/// Such a state is generally not on the surface (the step that crosses it starts inside; hardening
/// steps end slightly inside). Eq 22/29 assume f_n = 0, and the forward-Euler step they give keeps
/// f(σ) at its start value: a D-P drained plateau then stays up to one increment's stress below the
/// peak for good, because the correction acts only outside the surface. The multiplier is therefore
/// taken from the linearised consistency condition
///   f_{n+1} ≈ f_n + n_f : D : (Δε − Δλ n_g) + ∂f/∂p_c Δp_c = 0  ⇒  Δλ = (f_n + n_f:D:Δε)/(n_f:D:n_g + H),
/// which is eq 22/29 on the surface and pulls an inside start onto it. First order: the remaining
/// error is what `substep` and `implicit` remove.
#include "constitutive/state.h"

namespace soilsph {

/// Lower bound of the plastic denominator relative to its elastic part n_f:D:n_g (see below).
inline constexpr double kMinDenominatorFraction = 0.1;

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
    const double numerator = model.yield(sigma, start.pc) + ddot(n_f, elastic_stress_increment);
    // With strong softening (MCC dry side, H → −n_f:D:n_g) the forward-Euler Δλ diverges and the
    // exact hardening p_c·exp(θ tr Δε^p) underflows to 0 (found by the stress test). The
    // denominator is therefore kept ≥ 0.1 n_f:D:n_g, i.e. Δλ at most 10× the perfectly plastic
    // one; the correction then puts the state on the surface. Hardening steps are unaffected.
    const double elastic_part = ddot(n_f, D.stiffness(n_g));
    const double denominator =
        std::max(elastic_part + model.hardening_modulus(sigma, start.pc), kMinDenominatorFraction * elastic_part);
    if (numerator > 0.0 && elastic_part > 0.0) {
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
