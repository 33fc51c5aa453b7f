#pragma once
/// @file
/// Triaxial compression and extension of Mohr–Coulomb from an isotropic stress p_i, drained (radial
/// stress held at p_i) or undrained (ε_v = 0, total radial stress held), axial strain ε_a driven
/// (compression-positive; ε_a < 0 is extension). Derivation in docs/method/derivations.md.
/// With s = sinφ, t = sinψ, c cosφ, the sign σ = +1 (compression) or −1 (extension), and q = σ_a − σ_r:
///   drained    peak |q| = 2(c cosφ + p_i s)/(1 − σ s)   (the radial stress is the minor principal
///              stress in compression, the major in extension); elastic q = E ε_a, ε_v = (1 − 2ν) ε_a;
///              at the peak the flow of the edge, dε_v/dε_a = −2σ t/(1 − σ t)
///   undrained  elastic q = 3G ε_a, p' = p_i; first yield |q| = 2(c cosφ + p_i s)/(1 − σ s/3); then
///              along the failure line |q| = 2(c cosφ + p' s)/(1 − σ s/3), slope M_σ = 6s/(3 − σ s),
///              with dp'/d|ε_a| = 4K t · 3G / (6G − 2σ G t + 4K M_σ t): p' rises with ψ > 0
///              (dilatancy held back by the undrained condition) and stays with ψ = 0.
/// With a tension cut-off T reached first (low confinement): drained extension holds σ'_a = −T at
/// |q| = p_i + T with dε_v/dε_a = 1; undrained, the stresses that reach −T hold it while the other
/// rises (compression σ̇'_a = E ε̇_a; extension σ̇'_r = 3GK/(K + 4G/3)|ε̇_a|) to the corner
/// (2c cosφ − (1 + sinφ)T)/(1 − sinφ), then up the edge as above from the corner's p'.
#include "constitutive/models/mohr_coulomb.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

class MohrCoulombTriaxial {
 public:
  MohrCoulombTriaxial(const MohrCoulomb& model, double p_initial, bool undrained);

  /// |q| at first yield on the compression (σ = +1) or extension (σ = −1) side.
  double yield_q(int sign) const;
  /// ε_a at first yield (negative for extension).
  double yield_strain(int sign) const;
  /// The state at axial strain ε_a of a monotonic loading from the isotropic state.
  ReferencePoint at(double eps_a) const;

 private:
  double p_initial_;
  bool undrained_;
  double young_, poisson_, K_, G_;
  double sin_phi_, sin_psi_, cohesion_;  ///< cohesion_: c cosφ
  double cutoff_;                        ///< T, +∞ without a cut-off

  /// |q| where the cut-off is reached before any yield (+∞ where it cannot be).
  double cutoff_q(int sign) const;
  /// M_σ = 6 sinφ/(3 − σ sinφ), the failure line's slope on the compression (+1) or extension side.
  double failure_slope(int sign) const;
  /// Undrained: the rise of p' along the edge over |ε_a| = beyond.
  double edge_rise(int sign, double beyond) const;
  ReferencePoint drained_on_cutoff(double eps_a) const;
  ReferencePoint undrained_on_cutoff(double eps_a) const;
};

}  // namespace soilsph::verification
