#include "verification/closed_form/mohr_coulomb_triaxial.h"

#include <algorithm>
#include <cmath>

namespace soilsph::verification {

MohrCoulombTriaxial::MohrCoulombTriaxial(const MohrCoulomb& model, double p_initial, bool undrained)
    : p_initial_(p_initial),
      undrained_(undrained),
      young_(model.params().young_modulus),
      poisson_(model.params().poisson_ratio),
      K_(model.elasticity().at(0.0).K),
      G_(model.elasticity().at(0.0).G),
      sin_phi_(model.sin_phi()),
      sin_psi_(model.sin_psi()),
      cohesion_(0.5 * model.cohesion_term()) {}

double MohrCoulombTriaxial::yield_q(int sign) const {
  const double strength = 2.0 * (cohesion_ + p_initial_ * sin_phi_);
  // Drained, σ_r = p_i is the minor (compression) or major (extension) principal stress; undrained,
  // p' = p_i at first yield and σ_r = p' − q/3.
  return strength / (1.0 - sign * sin_phi_ / (undrained_ ? 3.0 : 1.0));
}

double MohrCoulombTriaxial::yield_strain(int sign) const {
  return sign * yield_q(sign) / (undrained_ ? 3.0 * G_ : young_);
}

ReferencePoint MohrCoulombTriaxial::at(double eps_a) const {
  const int sign = eps_a < 0.0 ? -1 : 1;
  const double eps_y = yield_strain(sign);
  const double elastic = sign * std::min(sign * eps_a, sign * eps_y);  // ε_a up to first yield
  const double beyond = std::max(sign * (eps_a - eps_y), 0.0);         // |ε_a| past first yield
  const double t = sin_psi_;
  if (!undrained_) {
    const double q = young_ * elastic;
    // dε_v/dε_a = −2σt/(1 − σt) over ε_a − ε_y = σ·beyond: dilation on either side.
    const double eps_v = (1.0 - 2.0 * poisson_) * elastic - 2.0 * t / (1.0 - sign * t) * beyond;
    return {eps_a, eps_v, p_initial_ + q / 3.0, q, 0.0};
  }
  const double M = 6.0 * sin_phi_ / (3.0 - sign * sin_phi_);
  const double d_gamma = 3.0 * G_ * beyond / (6.0 * G_ - 2.0 * sign * G_ * t + 4.0 * K_ * M * t);
  const double p = p_initial_ + 4.0 * K_ * t * d_gamma;
  const double q = 3.0 * G_ * elastic + sign * M * (p - p_initial_);
  return {eps_a, 0.0, p, q, 0.0};
}

}  // namespace soilsph::verification
