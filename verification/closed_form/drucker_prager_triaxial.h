#pragma once
/// @file
/// Drained triaxial compression of Drucker–Prager from an isotropic stress p_i: radial stress held at
/// −p_i, axial strain ε_a driven (compression-positive). Derivation in docs/method/verification.md.
///   elastic branch     q = E ε_a,  ε_v = (1 − 2ν) ε_a,  p = p_i + q/3
///   peak (eq 17, 19)   √J2 = q/√3, I1 = −3p = −3p_i − q  ⇒  q_peak = (3 α_φ p_i + k_c)/(1/√3 − α_φ)
///   perfectly plastic  stress fixed at the peak; the potential g = √J2 + α_ψ I1 gives
///                      dε_v/dε_a = −3 α_ψ / (1/√3 − α_ψ) (dilation for ψ > 0): matched α_ψ
///                      = tanψ/√(9 + 12 tan²ψ), or α_ψ = 3 sinψ as printed (eq 20)
#include "constitutive/models/drucker_prager.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

class DruckerPragerDrainedTriaxial {
 public:
  DruckerPragerDrainedTriaxial(const DruckerPrager& model, double p_initial);

  /// Deviatoric stress at which the path meets the cone (eq 17 with the constants of eq 19).
  double peak_q() const { return q_peak_; }
  /// Axial strain at first yield, q_peak / E.
  double yield_strain() const { return q_peak_ / young_; }
  /// The state at axial strain ε_a ≥ 0 of a monotonic loading.
  ReferencePoint at(double eps_a) const;

 private:
  double p_initial_;
  double young_;
  double poisson_;
  double q_peak_;
  double plastic_dilation_slope_;  ///< dε_v/dε_a on the plastic branch
};

}  // namespace soilsph::verification
