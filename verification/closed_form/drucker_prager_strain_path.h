#pragma once
/// @file
/// Drucker–Prager under an axisymmetric strain path with fixed ratios, from an isotropic stress p_i:
/// per unit axial strain (compression-positive) dε_v = r dε_a and dε_q = s dε_a, i.e. undrained triaxial
/// (r = 0, s = 1), oedometer (r = 1, s = 2/3) and isotropic (r = 3, s = 0). Derivation in
/// docs/method/derivations.md.
///   elastic   dp = K r dε_a, dq = 3G s dε_a, until the cone q = √3 (3 α_φ p + k_c) (eq 17, triaxial
///             compression: √J2 = q/√3, I1 = −3p);
///   plastic   the potential g = √J2 + α_ψ I1 gives per unit dλ dε_v^p = −3 α_ψ, dε_q^p = 1/√3; staying
///             on the cone, dq = 3√3 α_φ dp, fixes dλ/dε_a = 3(G s − √3 α_φ K r) / (√3 (G + 9 α_φ α_ψ K)).
/// Both branches are linear in ε_a. Valid while the stress stays in triaxial compression (q ≥ 0).
#include "constitutive/models/drucker_prager.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

class DruckerPragerStrainPath {
 public:
  DruckerPragerStrainPath(const DruckerPrager& model, double p_initial, double volume_ratio,
                          double shear_ratio);

  /// Axial strain at which the elastic path meets the cone (+∞ if it never does).
  double yield_strain() const { return eps_yield_; }
  /// The state at axial strain ε_a ≥ 0 of a monotonic loading (or of any programme below yield_strain()).
  ReferencePoint at(double eps_a) const;

 private:
  double p_initial_;
  double r_;
  double eps_yield_;
  double dp_elastic_, dq_elastic_;  ///< dp/dε_a, dq/dε_a on the elastic branch
  double dp_plastic_, dq_plastic_;  ///< on the cone
};

}  // namespace soilsph::verification
