#include "verification/closed_form/cam_clay_undrained.h"

#include <cmath>
#include <stdexcept>

#include "verification/closed_form/gsl_numerics.h"

namespace soilsph::verification {

CamClayUndrainedTriaxial::CamClayUndrainedTriaxial(const ModifiedCamClay& model, double p_initial, double ocr)
    : c_(model), p0_(p_initial), pc0_(ocr * p_initial) {
  if (ocr < 1.0 || ocr >= 2.0) throw std::invalid_argument("MCC undrained closed form: needs 1 <= OCR < 2");
  if (c_.pressure_dependent) {
    const double Lambda = c_.plastic_slope / c_.lambda_star;
    p_failure_ = p0_ * std::pow(ocr / 2.0, Lambda);
  } else {
    p_failure_ = find_root([&](double p) { return 2.0 * p - pc_at(p); }, 1e-12 * p0_, p0_);
  }
  q_yield_ = c_.M * std::sqrt(p0_ * (pc0_ - p0_));
  eps_yield_ = q_yield_ / (3.0 * c_.shear(p0_));
}

double CamClayUndrainedTriaxial::pc_at(double p) const {
  return pc0_ * std::exp(-c_.elastic_volume(p0_, p) / c_.plastic_slope);
}

double CamClayUndrainedTriaxial::q_at(double p) const {
  return c_.M * std::sqrt(std::max(p * (pc_at(p) - p), 0.0));
}

double CamClayUndrainedTriaxial::distance_to_csl(double p, double offset) const {
  // p_c(p') = 2p'_f exp(−ε_v^e(p'_f → p')/(λ*−κ*)), so 2p' − p_c = −2p' expm1(ln(p'_f/p') − ε_v^e/(λ*−κ*)),
  // evaluated from p'_f − p' without the cancellation of 2p' − p_c next to the CSL.
  const double relative = -offset / p;  // ln(p'_f/p') = log1p(relative)
  const double elastic =
      c_.pressure_dependent ? -c_.kappa_star * std::log1p(relative) : offset / c_.constant_moduli.K;
  return -2.0 * p * std::expm1(std::log1p(relative) - elastic / c_.plastic_slope);
}

double CamClayUndrainedTriaxial::strain_at(double p) const {
  // Plastic shear: dε_q^p = 2q/(M²(2p' − p_c)) dε_v^p with dε_v^p = −dp'/K, singular at p'_f.
  const auto plastic_rate = [&](double s, double offset) {  // offset = s − p'_f
    return 2.0 * q_at(s) / (c_.M * c_.M * distance_to_csl(s, offset)) / c_.bulk(s);
  };
  const double plastic = -integrate_to_log_singularity(plastic_rate, p0_, p, p_failure_);
  // Elastic shear ∫ dq/(3G): (q − q_y)/(3G) for constant G; for G = c p'/κ*, by parts,
  // ∫ dq/p' = q/p' − q_y/p'_0 − ∫_{p'}^{p'_0} q/s² ds, which avoids dq/dp' → ∞ at the NC start.
  double elastic = (q_at(p) - q_yield_) / (3.0 * c_.shear(p0_));
  if (c_.pressure_dependent) {
    const double by_parts = integrate([&](double s) { return q_at(s) / (s * s); }, p, p0_);
    elastic = c_.kappa_star / (3.0 * c_.shear_to_bulk) * (q_at(p) / p - q_yield_ / p0_ - by_parts);
  }
  return eps_yield_ + elastic + plastic;
}

ReferencePoint CamClayUndrainedTriaxial::at(double eps_a) const {
  if (eps_a <= eps_yield_) return {eps_a, 0.0, p0_, 3.0 * c_.shear(p0_) * eps_a, pc0_};
  // ε_a grows without bound as p' → p'_f (log singularity); beyond what is resolvable, p' = p'_f.
  const double p =
      find_root_before_singularity([&](double s) { return strain_at(s) - eps_a; }, p0_, p_failure_)
          .value_or(p_failure_);
  return {eps_a, 0.0, p, q_at(p), pc_at(p)};
}

}  // namespace soilsph::verification
