#pragma once
// Shared fixtures for the constitutive tests: Table 1 materials (tests/common) and random tensors.
#include <random>

#include "constitutive/material.h"
#include "tests/common/table1_materials.h"

namespace soilsph::test {

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
