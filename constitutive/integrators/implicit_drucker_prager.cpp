#include "constitutive/integrators/implicit_drucker_prager.h"

#include <cmath>

namespace soilsph {

State implicit_update(const DruckerPrager& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent) {
  const Moduli D = model.elasticity().at(0.0);
  const double alpha = model.alpha_phi(), alpha_psi = model.alpha_psi();
  // The trial's invariants from the start's and the increment's own parts, not from the summed
  // trial stress: where 2G·Δε dwarfs the stress (stiff soil, low pressure) the sum's components
  // round the start's I1 away, while I1 + 3K tr Δε keeps it (exactly, on an isochoric path).
  const Mat3 s_trial = deviator(start.stress) + 2.0 * D.G * deviator(strain_increment);
  const double sqrt_j2 = std::sqrt(0.5 * ddot(s_trial, s_trial));
  const double I1 = start.stress.trace() + 3.0 * D.K * strain_increment.trace();
  const double f_trial = sqrt_j2 + alpha * I1 - model.k_c();  // eq 17
  State next = start;
  next.plastic_multiplier = 0.0;
  if (f_trial <= 0.0) {
    next.stress = start.stress + D.stiffness(strain_increment);
    if (tangent) *tangent = voigt_isotropic_stiffness(D.K, D.G);
    return next;
  }
  const double A = D.G + 9.0 * alpha * D.K * alpha_psi;  // n_f : D : n_g (denominator of eq 22)
  const double d_lambda = f_trial / A;

  // On the cone √J2 = k_c − α_φ I1 (= √J2_tr − GΔλ, computed without its cancellation near the apex).
  const double I1_next = I1 - 9.0 * D.K * alpha_psi * d_lambda;
  const double sqrt_j2_next = model.k_c() - alpha * I1_next;
  if (sqrt_j2_next > 0.0) {  // return to the cone
    next.stress = sqrt_j2_next / sqrt_j2 * s_trial + I1_next / 3.0 * Mat3::Identity();
    // dε^p = Δλ (s_tr/(2√J2_tr) + α_ψ I), whose parts are orthogonal: dε^p:dε^p = Δλ² (½ + 3α_ψ²).
    accumulate_plastic_strain_from_squared_norm(next, d_lambda * d_lambda * (0.5 + 3.0 * alpha_psi * alpha_psi));
    next.plastic_multiplier = d_lambda;
    if (tangent) {
      // σ = σ_tr − Δλ(√2 G n + 3K α_ψ I), n = s_tr/‖s_tr‖, ‖s_tr‖ = √2 √J2_tr:
      // C = D − (√2 G n + 3K α_ψ I) ⊗ (√2 G n + 3K α_φ I)/A − 2G (G Δλ/√J2_tr)(𝕀_dev − n ⊗ n).
      const Mat3 n = s_trial / (std::sqrt(2.0) * sqrt_j2);
      const Mat3 flow = std::sqrt(2.0) * D.G * n + 3.0 * D.K * alpha_psi * Mat3::Identity();
      const Mat3 normal = std::sqrt(2.0) * D.G * n + 3.0 * D.K * alpha * Mat3::Identity();
      *tangent = voigt_isotropic_stiffness(D.K, D.G) - voigt_outer(flow, normal) / A -
                 2.0 * D.G * (D.G * d_lambda / sqrt_j2) * (voigt_deviatoric_projector() - voigt_outer(n, n));
    }
    return next;
  }
  // Past the apex: the apex itself, whose stress does not depend on the increment.
  next.stress = model.apex_first_invariant() / 3.0 * Mat3::Identity();
  accumulate_plastic_strain(next, strain_increment - D.compliance(next.stress - start.stress));
  next.plastic_multiplier = sqrt_j2 / D.G;  // the deviatoric return √J2_tr/G (≥ 0)
  if (tangent) tangent->setZero();
  return next;
}

}  // namespace soilsph
