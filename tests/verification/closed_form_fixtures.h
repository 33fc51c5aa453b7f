#pragma once
// Fixtures for the closed-form tests: the Table 1 soils (tests/common) and triaxial stress states.
#include "tests/common/table1_materials.h"

namespace soilsph::test {

/// σ of a triaxial compression state (axial = x), tension-positive, from compression-positive p, q.
inline Mat3 triaxial_stress(double p, double q) {
  Mat3 s = isotropic_stress(p);
  s(0, 0) -= 2.0 * q / 3.0;
  s(1, 1) += q / 3.0;
  s(2, 2) += q / 3.0;
  return s;
}

}  // namespace soilsph::test
