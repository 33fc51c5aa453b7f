#pragma once
// Shared fixtures for the constitutive tests: Table 1 materials built in code and random tensors.
#include <random>

#include "constitutive/material.h"

namespace soilsph::test {

inline DruckerPrager::Params table1_drucker_prager(double cohesion = 0.0, double dilatancy = 0.0) {
  DruckerPrager::Params p{};
  p.density = 2000.0;
  p.young_modulus = 1.0e6;
  p.poisson_ratio = 0.3;
  p.friction_angle = 35.0;
  p.cohesion = cohesion;
  p.dilatancy_angle = dilatancy;
  return p;
}

inline ModifiedCamClay::Params table1_cam_clay(Elasticity::Kind elasticity) {
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
  return p;
}

/// A random symmetric tensor with entries uniform in [-scale, scale].
inline Mat3 random_symmetric(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) a(i, j) = a(j, i) = u(rng);
  return a;
}

/// A random skew tensor with entries uniform in [-scale, scale].
inline Mat3 random_skew(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Mat3 w = Mat3::Zero();
  w(0, 1) = u(rng), w(0, 2) = u(rng), w(1, 2) = u(rng);
  return w - w.transpose();
}

}  // namespace soilsph::test
