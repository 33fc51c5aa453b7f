#pragma once
/// @file
/// The Modified Cam-Clay constants the closed forms use, compression-positive:
///   λ* = λ/(1+e0), κ* = κ/(1+e0), and the hardening law (eq 27) p_c = p_c0 exp(ε_v^p / (λ* − κ*));
///   elasticity K(p) = p/κ*, G = c K with c = 3(1−2ν)/(2(1+ν)) (pressure-dependent) or constant K, G.
/// The pressure floor of the pressure-dependent law is not modelled: the closed forms require p above it.
#include <cmath>

#include "constitutive/models/modified_cam_clay.h"

namespace soilsph::verification {

struct CamClayConstants {
  explicit CamClayConstants(const ModifiedCamClay& model)
      : M(model.M()),
        lambda_star(model.params().compression_index / (1.0 + model.params().initial_void_ratio)),
        kappa_star(model.params().swelling_index / (1.0 + model.params().initial_void_ratio)),
        plastic_slope(lambda_star - kappa_star),
        shear_to_bulk(1.5 * (1.0 - 2.0 * model.params().poisson_ratio) /
                      (1.0 + model.params().poisson_ratio)),
        pressure_dependent(model.elasticity().kind() == Elasticity::Kind::PressureDependent),
        constant_moduli(model.elasticity().at(0.0)) {}

  double M;
  double lambda_star;
  double kappa_star;
  double plastic_slope;  ///< λ* − κ*: plastic volume per unit ln p_c
  double shear_to_bulk;  ///< G/K at constant ν
  bool pressure_dependent;
  Moduli constant_moduli;  ///< K, G of constant elasticity

  double bulk(double p) const { return pressure_dependent ? p / kappa_star : constant_moduli.K; }
  double shear(double p) const {
    return pressure_dependent ? shear_to_bulk * p / kappa_star : constant_moduli.G;
  }
  /// Elastic volumetric strain from p0 to p: κ* ln(p/p0) or (p − p0)/K.
  double elastic_volume(double p0, double p) const {
    return pressure_dependent ? kappa_star * std::log(p / p0) : (p - p0) / constant_moduli.K;
  }
  /// Plastic volumetric strain that takes p_c0 to p_c (eq 27 inverted).
  double plastic_volume(double pc0, double pc) const { return plastic_slope * std::log(pc / pc0); }
  /// Plastic shear per plastic volume of associated flow, (∂f/∂q)/(∂f/∂p) = 2q / (M²(2p − p_c)).
  double dilatancy_ratio(double p, double q, double pc) const { return 2.0 * q / (M * M * (2.0 * p - pc)); }
};

}  // namespace soilsph::verification
