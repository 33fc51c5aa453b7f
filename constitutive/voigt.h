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

namespace soilsph {

/// The 6×6 matrix of the fourth-order tensor a ⊗ b acting on a Voigt strain: (a ⊗ b) : dε = a (b : dε).
inline Mat6 voigt_outer(const Mat3& a, const Mat3& b) {
  return stress_to_voigt(a) * stress_to_voigt(b).transpose();
}

/// The deviatoric projector 𝕀_dev (dε ↦ dev dε) from Voigt strain to Voigt stress.
inline Mat6 voigt_deviatoric_projector() {
  Mat6 P = Mat6::Zero();
  P.topLeftCorner<3, 3>().setConstant(-1.0 / 3.0);
  for (int k = 0; k < 3; ++k) P(k, k) += 1.0, P(k + 3, k + 3) = 0.5;
  return P;
}

/// The isotropic stiffness K 1⊗1 + 2G 𝕀_dev in Voigt form.
inline Mat6 voigt_isotropic_stiffness(double K, double G) {
  Mat6 D = 2.0 * G * voigt_deviatoric_projector();
  D.topLeftCorner<3, 3>().array() += K;
  return D;
}

}  // namespace soilsph
