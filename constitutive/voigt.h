#pragma once
/// @file
/// Voigt notation for the material-point driver and tangents. Order: xx, yy, zz, xy, yz, xz.
/// Strains carry engineering shears (γ_xy = 2ε_xy), stresses plain components, so that σ·ε in
/// Voigt form equals σ:ε and a 6×6 tangent maps Voigt strain to Voigt stress.
#include <Eigen/Core>

#include "constitutive/tensor.h"

namespace soilsph {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

inline constexpr int kVoigtRow[6] = {0, 1, 2, 0, 1, 0};
inline constexpr int kVoigtCol[6] = {0, 1, 2, 1, 2, 2};

inline Vec6 stress_to_voigt(const Mat3& s) {
  Vec6 v;
  for (int k = 0; k < 6; ++k) v(k) = s(kVoigtRow[k], kVoigtCol[k]);
  return v;
}
inline Mat3 stress_from_voigt(const Vec6& v) {
  Mat3 s;
  for (int k = 0; k < 6; ++k) s(kVoigtRow[k], kVoigtCol[k]) = s(kVoigtCol[k], kVoigtRow[k]) = v(k);
  return s;
}
inline Vec6 strain_to_voigt(const Mat3& e) {
  Vec6 v = stress_to_voigt(e);
  v.tail<3>() *= 2.0;
  return v;
}
inline Mat3 strain_from_voigt(Vec6 v) {
  v.tail<3>() *= 0.5;
  return stress_from_voigt(v);
}

}  // namespace soilsph
