#include "verification/closed_form/cam_clay_drained.h"

#include <cmath>
#include <stdexcept>

#include "verification/closed_form/gsl_numerics.h"

namespace soilsph::verification {

CamClayDrainedTriaxial::CamClayDrainedTriaxial(const ModifiedCamClay& model, double p_initial, double ocr)
    : c_(model), p_initial_(p_initial), pc0_(ocr * p_initial) {
  if (c_.M >= 3.0) throw std::invalid_argument("MCC drained closed form: needs M < 3");
  if (ocr < 1.0) throw std::invalid_argument("MCC drained closed form: needs OCR >= 1");
  // q² = M² (p'_i + q/3)(p_c0 − p'_i − q/3)  ⇔  A q² + B q + C = 0.
  const double MM = c_.M * c_.M;
  const double A = 1.0 + MM / 9.0;
  const double B = -MM * (pc0_ - 2.0 * p_initial_) / 3.0;
  const double C = -MM * p_initial_ * (pc0_ - p_initial_);
  q_yield_ = (-B + std::sqrt(B * B - 4.0 * A * C)) / (2.0 * A);
  if (q_yield_ >= c_.M * p_at(q_yield_))
    throw std::invalid_argument("MCC drained closed form: yield on the dry side");
}

double CamClayDrainedTriaxial::pc_at(double q) const {
  if (q <= q_yield_) return pc0_;
  const double p = p_at(q);
  return p + q * q / (c_.M * c_.M * p);
}

double CamClayDrainedTriaxial::volumetric_strain_at(double q) const {
  return c_.elastic_volume(p_initial_, p_at(q)) + c_.plastic_volume(pc0_, pc_at(q));
}

double CamClayDrainedTriaxial::elastic_shear(double q) const {
  if (c_.pressure_dependent) return c_.kappa_star / c_.shear_to_bulk * std::log(p_at(q) / p_initial_);
  return q / (3.0 * c_.constant_moduli.G);
}

double CamClayDrainedTriaxial::axial_strain_at(double q) const {
  const double MM = c_.M * c_.M;
  const auto plastic_shear_rate = [&](double s, double offset) {  // offset = s − q_f
    const double p = p_at(s);
    const double pc = p + s * s / (MM * p);
    const double dpc_dq = 1.0 / 3.0 + 2.0 * s / (MM * p) - s * s / (3.0 * MM * p * p);
    // 2η/(M² − η²) with M − η = (1 − M/3)(q_f − q)/p', free of cancellation next to the CSL.
    const double eta = s / p;
    const double dilatancy = 2.0 * eta / ((c_.M + eta) * (1.0 - c_.M / 3.0) * (-offset) / p);
    return c_.plastic_slope * dpc_dq / pc * dilatancy;
  };
  const double plastic_shear =
      q > q_yield_ ? integrate_to_log_singularity(plastic_shear_rate, q_yield_, q, failure_q()) : 0.0;
  return volumetric_strain_at(q) / 3.0 + elastic_shear(q) + plastic_shear;
}

ReferencePoint CamClayDrainedTriaxial::at(double eps_a) const {
  double q = 0.0;
  if (eps_a > 0.0) {
    // ε_a grows without bound as q → q_f (log singularity); beyond what is resolvable, q = q_f.
    q = find_root_before_singularity([&](double s) { return axial_strain_at(s) - eps_a; }, 0.0, failure_q(),
                                     1e-14, 1e-12 * p_initial_)
            .value_or(failure_q());
  }
  return {eps_a, volumetric_strain_at(q), p_at(q), q, pc_at(q)};
}

}  // namespace soilsph::verification
