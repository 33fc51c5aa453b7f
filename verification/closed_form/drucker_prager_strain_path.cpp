#include "verification/closed_form/drucker_prager_strain_path.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace soilsph::verification {

DruckerPragerStrainPath::DruckerPragerStrainPath(const DruckerPrager& model, double p_initial,
                                                 double volume_ratio, double shear_ratio)
    : p_initial_(p_initial), r_(volume_ratio) {
  const Moduli D = model.elasticity().at(p_initial);
  const double alpha = model.alpha_phi(), root3 = std::sqrt(3.0);
  const double alpha_psi = model.alpha_psi();  // g = √J2 + α_ψ I1
  dp_elastic_ = D.K * volume_ratio;
  dq_elastic_ = 3.0 * D.G * shear_ratio;
  // Cone in the (p, q) plane: q = √3 (3α p + k_c); the elastic path q = dq/dp · (p − p_i) meets it
  // where the distance to the cone, q_cone − q, vanishes.
  const double gap0 = root3 * (3.0 * alpha * p_initial + model.k_c());
  const double closing = dq_elastic_ - 3.0 * root3 * alpha * dp_elastic_;  // d(q − q_cone)/dε_a
  eps_yield_ = closing > 0.0 ? gap0 / closing : std::numeric_limits<double>::infinity();
  const double rate = closing / (root3 * (D.G + 9.0 * alpha * D.K * alpha_psi));  // dλ/dε_a
  dp_plastic_ = D.K * (volume_ratio + 3.0 * alpha_psi * rate);
  dq_plastic_ = 3.0 * root3 * alpha * dp_plastic_;
  if (!std::isfinite(gap0) || gap0 < 0.0)
    throw std::invalid_argument("D-P strain path: start outside the cone");
}

ReferencePoint DruckerPragerStrainPath::at(double eps_a) const {
  const double elastic = std::min(eps_a, eps_yield_), plastic = std::max(eps_a - eps_yield_, 0.0);
  const double p = p_initial_ + dp_elastic_ * elastic + dp_plastic_ * plastic;
  const double q = dq_elastic_ * elastic + dq_plastic_ * plastic;
  if (q < 0.0)
    throw std::domain_error("D-P strain path: the closed form covers triaxial compression (q >= 0) only");
  return {eps_a, r_ * eps_a, p, q, 0.0};
}

}  // namespace soilsph::verification
