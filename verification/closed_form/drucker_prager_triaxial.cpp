#include "verification/closed_form/drucker_prager_triaxial.h"

#include <cmath>
#include <stdexcept>

namespace soilsph::verification {

DruckerPragerDrainedTriaxial::DruckerPragerDrainedTriaxial(const DruckerPrager& model, double p_initial)
    : p_initial_(p_initial), young_(model.params().young_modulus), poisson_(model.params().poisson_ratio) {
  const double root3 = std::sqrt(3.0);
  const double alpha = model.alpha_phi();
  if (alpha >= 1.0 / root3) throw std::invalid_argument("D-P triaxial: alpha_phi >= 1/sqrt(3), no peak");
  q_peak_ = (3.0 * alpha * p_initial + model.k_c()) / (1.0 / root3 - alpha);
  // Plastic strain rates of the potential g = √J2 + α_ψ I1 in triaxial compression, where
  // s/(2√J2) = diag(−1/√3, 1/(2√3), 1/(2√3)) (tension-positive): per unit dλ, compression-positive,
  // dε_a^p = 1/√3 − α_ψ and dε_v^p = −3 α_ψ. The stress is fixed, so the elastic strain is too
  // (docs/method/derivations.md; α_ψ = 3 sinψ for the printed eq 20).
  const double alpha_psi = model.alpha_psi();
  const double axial_rate = 1.0 / root3 - alpha_psi;
  if (axial_rate <= 0.0)
    throw std::invalid_argument(
        "D-P triaxial: the potential's alpha_psi >= 1/sqrt(3), no axial flow (paper-eq20 with psi >= 11.1 "
        "degrees)");
  plastic_dilation_slope_ = -3.0 * alpha_psi / axial_rate;
}

ReferencePoint DruckerPragerDrainedTriaxial::at(double eps_a) const {
  const double eps_y = yield_strain();
  const double eps_v_y = (1.0 - 2.0 * poisson_) * std::min(eps_a, eps_y);
  const double q = young_ * std::min(eps_a, eps_y);
  const double eps_v = eps_v_y + plastic_dilation_slope_ * std::max(eps_a - eps_y, 0.0);
  return {eps_a, eps_v, p_initial_ + q / 3.0, q, 0.0};
}

}  // namespace soilsph::verification
