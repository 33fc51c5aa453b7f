#pragma once
// Materials for the closed-form tests: the paper's Table 1 soils, MCC with either elasticity.
#include "constitutive/material.h"

namespace soilsph::test {

inline DruckerPrager table1_drucker_prager(double cohesion = 0.0, double dilatancy = 0.0) {
  DruckerPrager::Params p{};
  p.density = 2000.0;
  p.young_modulus = 1.0e6;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.cohesion = cohesion;
  p.dilatancy_angle = dilatancy;
  return DruckerPrager(p);
}

inline ModifiedCamClay table1_cam_clay(Elasticity::Kind elasticity, double swelling_index = 0.019) {
  ModifiedCamClay::Params p{};
  p.density = 2000.0;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.compression_index = 0.085;
  p.swelling_index = swelling_index;
  p.initial_void_ratio = 0.68;
  p.elasticity = elasticity;
  p.young_modulus = 1.0e6;
  p.elastic_pressure_floor = 1.0e3;
  return ModifiedCamClay(p);
}

/// σ of a triaxial compression state (axial = x), tension-positive, from compression-positive p, q.
inline Mat3 triaxial_stress(double p, double q) {
  Mat3 s = isotropic_stress(p);
  s(0, 0) -= 2.0 * q / 3.0;
  s(1, 1) += q / 3.0;
  s(2, 2) += q / 3.0;
  return s;
}

}  // namespace soilsph::test
