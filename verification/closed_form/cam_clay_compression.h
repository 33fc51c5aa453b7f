#pragma once
/// @file
/// Isotropic and oedometric (K0) compression of Modified Cam-Clay, with unloading and reloading, from
/// p'_i with p_c0 = R0 p'_i. Derivations in docs/method/verification.md.
///  - Isotropic: ε_v = ε_v^e(p'_i → p') + (λ*−κ*) ln(p_c/p_c0) holds on any path; on the NCL p_c = p',
///    slope dε_v/d ln p' = λ* = λ/(1+e0) (pressure-dependent elasticity), on unloading κ* = κ/(1+e0).
///    Constant elasticity: the NCL point by root finding (GSL).
///  - Oedometer (pressure-dependent elasticity only; the problem is then self-similar): on the yield
///    surface p_c = p' g(η), g = 1 + η²/M², and ε_r = 0 (dε_q = 2/3 dε_v) gives the autonomous ODE
///      dη/d ln p' = −N(η)/D(η),  N = bη + (λ*−κ*) h − 2λ*/3,  D = b + (λ*−κ*) k (h − 2/3),
///    with b = κ*/(3c), h = 2η/(M² − η²), k = 2η/(M² + η²); ln p' follows from η by quadrature and
///    ε_a = ε_v = ε_v,y + λ* ln(p'/p'_y) + (λ*−κ*) ln(g(η)/g(η_y)). Its fixed point N(η_K0) = 0 is the
///    K0 line: K0 = σ'_r/σ'_a = (3 − η_K0)/(3 + 2η_K0), along which dε_a/d ln σ'_a = λ*.
///    Unloading is elastic: p' = p'_t exp((ε_a − ε_t)/κ*), q = q_t + 2c (p' − p'_t).
#include <span>
#include <vector>

#include "verification/closed_form/cam_clay_constants.h"
#include "verification/closed_form/reference_point.h"

namespace soilsph::verification {

/// η = q/p' on the oedometric normal compression line of MCC with pressure-dependent elasticity.
double cam_clay_k0_stress_ratio(const ModifiedCamClay& model);
/// K0 = σ'_r/σ'_a = (3 − η)/(3 + 2η) for the stress ratio η of a triaxial compression state.
inline double k0_from_stress_ratio(double eta) {
  return (3.0 - eta) / (3.0 + 2.0 * eta);
}

class CamClayIsotropicCompression {
 public:
  CamClayIsotropicCompression(const ModifiedCamClay& model, double p_initial, double ocr);
  /// The states at the volumetric strains `eps_v` (compression-positive), visited in order.
  std::vector<ReferencePoint> curve(std::span<const double> eps_v) const;

 private:
  CamClayConstants c_;
  double p_initial_;
  double pc0_;
};

class CamClayOedometer {
 public:
  CamClayOedometer(const ModifiedCamClay& model, double p_initial, double ocr);
  double k0_stress_ratio() const { return eta_k0_; }
  double yield_strain() const { return eps_yield_; }
  /// The states at the axial strains `eps_a` (compression-positive), visited in order.
  std::vector<ReferencePoint> curve(std::span<const double> eps_a) const;

 private:
  ReferencePoint loading(double eps_a) const;      ///< first loading: elastic, then along the ODE
  double log_pressure_change(double depth) const;  ///< ln(p'/p'_y) at depth ln(|η_y − η_K0|/|η − η_K0|)
  double numerator(double eta, double offset) const;  ///< N(η), offset = η − η_K0
  double denominator(double eta) const;

  CamClayConstants c_;
  double p_initial_;
  double pc0_;
  double b_;
  double eta_k0_;
  double p_yield_;
  double eta_yield_;
  double eps_yield_;
};

}  // namespace soilsph::verification
