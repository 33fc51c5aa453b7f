#pragma once
/// @file
/// Sign convention, tensor types and stress invariants: stated once, used everywhere.
///
/// Internally stress and strain are **tension-positive** (paper eq 9–10): a compressed soil has
/// negative normal stresses. The soil-mechanics quantities returned here are **compression-positive**:
///   p   = -tr(σ)/3                 (eq 10, positive in compression)
///   q   = sqrt(3/2 s:s)            (eq 25)
///   ε_v = -tr(ε)                   (positive in compaction)
/// All quantities are SI (Pa, m, s). Plane strain keeps the full 3×3 stress: σ_zz evolves.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace soilsph {

using Mat3 = Eigen::Matrix3d;  ///< symmetric stress/strain or skew spin, tension-positive
using Vec3 = Eigen::Vector3d;

inline const Mat3& identity3() {
  static const Mat3 I = Mat3::Identity();
  return I;
}

/// First invariant I1 = tr σ (eq 18), tension-positive.
inline double first_invariant(const Mat3& s) { return s.trace(); }
/// Deviator s = σ - tr(σ)/3 I.
inline Mat3 deviator(const Mat3& s) { return s - (s.trace() / 3.0) * Mat3::Identity(); }
/// Double contraction a:b.
inline double ddot(const Mat3& a, const Mat3& b) { return (a.array() * b.array()).sum(); }
/// Second deviatoric invariant J2 = ½ s:s (eq 18).
inline double second_deviatoric_invariant(const Mat3& sigma) {
  const Mat3 s = deviator(sigma);
  return 0.5 * ddot(s, s);
}
/// Mean effective stress, compression-positive (eq 10).
inline double mean_pressure(const Mat3& sigma) { return -sigma.trace() / 3.0; }
/// Deviatoric (von Mises) stress q = sqrt(3 J2) (eq 25).
inline double deviatoric_stress(const Mat3& sigma) {
  return std::sqrt(3.0 * second_deviatoric_invariant(sigma));
}
/// Volumetric strain, compression-positive.
inline double volumetric_strain(const Mat3& eps) { return -eps.trace(); }
/// Equivalent deviatoric strain ε_q = sqrt(2/3 e:e); equals 2/3 (ε_a − ε_r) on axisymmetric paths.
inline double deviatoric_strain(const Mat3& eps) {
  const Mat3 e = deviator(eps);
  return std::sqrt(2.0 / 3.0 * ddot(e, e));
}

/// Lode angle θ ∈ [-π/6, π/6] from sin 3θ = -(3√3/2) J3 / J2^{3/2} (θ = +π/6 in triaxial
/// compression with the tension-positive sign convention). Returns 0 for a hydrostatic state.
inline double lode_angle(const Mat3& sigma) {
  const Mat3 s = deviator(sigma);
  const double J2 = 0.5 * ddot(s, s);
  if (J2 <= 1e-300) return 0.0;
  const double J3 = s.determinant();
  double x = -1.5 * std::sqrt(3.0) * J3 / std::pow(J2, 1.5);
  x = std::clamp(x, -1.0, 1.0);
  return std::asin(x) / 3.0;
}

/// Isotropic tensor with mean pressure p (compression-positive): σ = -p I.
inline Mat3 isotropic_stress(double p) { return -p * Mat3::Identity(); }

}  // namespace soilsph
