#pragma once
/// @file
/// Undrained (constant-volume) triaxial compression of Modified Cam-Clay from p'_0 with
/// p_c0 = R0 p'_0, normally or lightly overconsolidated (1 ≤ R0 < 2, the wet side). Derivation in
/// docs/method/verification.md (after Wood 1990, §7.3 and §11.2).
///  - Elastic: ε_v^e = 0 ⇒ p' = p'_0 (both elasticities), q = 3G(p'_0) ε_a up to the yield surface,
///    q_y = M √(p'_0 (p_c0 − p'_0)).
///  - Plastic: ε_v^p = −ε_v^e(p'_0 → p') fixes p_c(p') = p_c0 exp(−ε_v^e/(λ*−κ*)); the path is the
///    yield surface q = M √(p'(p_c − p')). Pressure-dependent elasticity: p_c = p_c0 (p'_0/p')^{κ/(λ−κ)},
///    and the critical state p_c = 2p' gives p'_f = p'_0 (R0/2)^Λ, Λ = (λ−κ)/λ, q_f = M p'_f.
///    Constant elasticity: p_c = p_c0 exp((p'_0 − p')/(K(λ*−κ*))) and p'_f solves 2p' = p_c(p') (Brent).
///  - ε_a = ε_q (no volume change) = q_y/(3G_0) + ∫ dq/(3G) + ∫_{p'}^{p'_0} 2q/(M²(2s − p_c) K) ds: the
///    elastic shear plus the flow rule's shear per plastic volume dε_v^p = −dp'/K (GSL quadrature; the
///    elastic part in closed form for constant G, by parts for G ∝ p').
#include "verification/closed_form/cam_clay_constants.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

class CamClayUndrainedTriaxial {
 public:
  CamClayUndrainedTriaxial(const ModifiedCamClay& model, double p_initial, double ocr);

  double failure_p() const { return p_failure_; }  ///< p'_f on the critical-state line
  double failure_q() const { return c_.M * p_failure_; }
  double yield_q() const { return q_yield_; }
  double yield_strain() const { return eps_yield_; }
  /// p_c on the constant-volume plastic path at p'.
  double pc_at(double p) const;
  /// q on the yield surface at p' of the plastic path.
  double q_at(double p) const;
  /// Axial strain at p' ∈ (p'_f, p'_0] of the plastic path, by quadrature.
  double strain_at(double p) const;
  /// The state at axial strain ε_a ≥ 0 of a monotonic loading.
  ReferencePoint at(double eps_a) const;

 private:
  double distance_to_csl(double p,
                         double offset) const;  ///< 2p' − p_c(p') on the plastic path, offset = p' − p'_f

  CamClayConstants c_;
  double p0_;
  double pc0_;
  double p_failure_;
  double q_yield_;
  double eps_yield_;
};

}  // namespace soilsph::verification
