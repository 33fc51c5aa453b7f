#pragma once
// The paper's Table 1 soils built in code for every test layer: D-P (E = 1 MPa, ν = 0.3, φ = 35°,
// c and ψ optional) and MCC (λ = 0.085, κ = 0.019, e0 = 0.68, either elasticity).
#include "constitutive/material.h"

namespace soilsph::test {

inline DruckerPrager::Params table1_drucker_prager_params(double cohesion = 0.0, double dilatancy = 0.0) {
  DruckerPrager::Params p{};
  p.density = 2000.0;
  p.young_modulus = 1.0e6;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.cohesion = cohesion;
  p.dilatancy_angle = dilatancy;
  p.integrator = Integrator::Explicit;  // the paper's scheme, which these tests were written for
  return p;
}

inline ModifiedCamClay::Params table1_cam_clay_params(
    Elasticity::Kind elasticity = Elasticity::Kind::PressureDependent, double swelling_index = 0.019) {
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
  p.integrator = Integrator::Explicit;  // the paper's scheme, which these tests were written for
  return p;
}

inline DruckerPrager table1_drucker_prager(double cohesion = 0.0, double dilatancy = 0.0) {
  return DruckerPrager(table1_drucker_prager_params(cohesion, dilatancy));
}

inline ModifiedCamClay table1_cam_clay(Elasticity::Kind elasticity = Elasticity::Kind::PressureDependent,
                                       double swelling_index = 0.019) {
  return ModifiedCamClay(table1_cam_clay_params(elasticity, swelling_index));
}

inline LinearElastic linear_elastic(double E = 1.0e6, double nu = 0.3) { return LinearElastic({2000.0, E, nu}); }

}  // namespace soilsph::test
