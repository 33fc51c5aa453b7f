#pragma once
// Materials of the verification tests, built in code: the paper's Table 1 and variants.
#include "constitutive/material.h"

namespace soilsph::test {

inline LinearElastic linear_elastic(double E = 1.0e6, double nu = 0.3) {
  return LinearElastic({2000.0, E, nu});
}

inline DruckerPrager drucker_prager(double cohesion = 0.0, double dilatancy = 0.0) {
  DruckerPrager::Params p{};
  p.density = 2000.0;
  p.young_modulus = 1.0e6;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.cohesion = cohesion;
  p.dilatancy_angle = dilatancy;
  return DruckerPrager(p);
}

inline ModifiedCamClay cam_clay(Elasticity::Kind elasticity = Elasticity::Kind::PressureDependent) {
  ModifiedCamClay::Params p{};
  p.density = 2000.0;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.compression_index = 0.085;
  p.swelling_index = 0.019;
  p.initial_void_ratio = 0.68;
  p.elasticity = elasticity;
  p.young_modulus = 1.0e6;
  p.elastic_pressure_floor = 1.0e3;
  return ModifiedCamClay(p);
}

}  // namespace soilsph::test
