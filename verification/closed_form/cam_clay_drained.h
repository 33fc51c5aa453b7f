#pragma once
/// @file
/// Drained triaxial compression of Modified Cam-Clay from p'_i (radial stress held at −p'_i, so the
/// stress path is p' = p'_i + q/3, slope 3) with p_c0 = R0 p'_i, yield on the wet side. Derivation in
/// docs/method/verification.md.
///  - Failure on the CSL q = M p': q_f = 3 M p'_i / (3 − M) (needs M < 3).
///  - First yield: the positive root of q² = M² p'(p_c0 − p') with p' = p'_i + q/3.
///  - On the yield surface p_c = p' + q²/(M² p'), so in closed form
///      ε_v(q) = ε_v^e(p'_i → p') + (λ* − κ*) ln(p_c/p_c0)
///    with ε_v^e = κ* ln(p'/p'_i) (pressure-dependent) or (p' − p'_i)/K (constant).
///  - ε_a = ε_v/3 + ε_q, ε_q = ε_q^e + ε_q^p: ε_q^e = q/(3G) or (κ*/c) ln(p'/p'_i) (G = cK = c p'/κ*,
///    dq = 3dp'), and ε_q^p = ∫ (λ*−κ*) (dp_c/dq)/p_c · 2η/(M² − η²) dq by quadrature (GSL).
#include "verification/closed_form/cam_clay_constants.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

class CamClayDrainedTriaxial {
 public:
  CamClayDrainedTriaxial(const ModifiedCamClay& model, double p_initial, double ocr);

  double failure_q() const { return 3.0 * c_.M * p_initial_ / (3.0 - c_.M); }
  double yield_q() const { return q_yield_; }
  /// p_c of the state on the path at deviatoric stress q (p_c0 before first yield).
  double pc_at(double q) const;
  /// Volumetric strain at q, closed form.
  double volumetric_strain_at(double q) const;
  /// Axial strain at q, with the plastic shear by quadrature.
  double axial_strain_at(double q) const;
  /// The state at axial strain ε_a ≥ 0 of a monotonic loading.
  ReferencePoint at(double eps_a) const;

 private:
  double p_at(double q) const { return p_initial_ + q / 3.0; }
  double elastic_shear(double q) const;

  CamClayConstants c_;
  double p_initial_;
  double pc0_;
  double q_yield_;
};

}  // namespace soilsph::verification
