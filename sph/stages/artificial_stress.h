#pragma once
/// @file
/// Artificial stress against the tensile instability (Gray, Monaghan & Swift 2001, Comput. Methods
/// Appl. Mech. Eng. 190:6641; used for soil by Bui et al. 2008, Int. J. Numer. Anal. Meth. Geomech.
/// 32:1537). In the principal axes of the in-plane stress, a tensile principal stress σ' > 0 gets
///   R' = −ε σ'/ρ²   (R' = 0 for σ' ≤ 0),
/// rotated back to x–y; the momentum equation adds Σ_j m_j (R_i + R_j) f_ij^n ∇_i W_ij with
/// f_ij = W_ij / W(Δp), Δp the initial particle spacing. Defaults ε = 0.5, n = 2.55 (Bui et al. 2008).
/// Cohesionless soil carries almost no tension (the D-P apex is I1 = 0), so the term only acts on
/// transient tension; it is switchable ([numerics] artificial_stress).
#include <cmath>
#include <optional>
#include <utility>

#include <Eigen/Eigenvalues>

#include "sph/kernel.h"
#include "sph/particles.h"
#include "sph/stages/kernel_ratio_power.h"

namespace soilsph::sph {

/// The term's parameters, off unless built with them (scene key [numerics] artificial_stress).
class ArtificialStress {
 public:
  ArtificialStress() = default;
  /// ε, n, and the kernel and Δp that f = W / W(Δp) is taken of.
  template <class Kernel>
  ArtificialStress(double epsilon, double exponent, const Kernel& kernel, double particle_spacing)
      : epsilon_(epsilon),
        f_power_(std::in_place, exponent, kernel.value(particle_spacing), kernel.value(0.0)) {}

  bool enabled() const { return f_power_.has_value(); }
  double epsilon() const { return epsilon_; }  ///< ε
  /// f^n of a pair with W_ij = w; only when enabled.
  double weight(double w) const { return (*f_power_)(w); }

 private:
  double epsilon_ = 0.0;
  std::optional<KernelRatioPower> f_power_;
};

/// Whether particle i has a nonzero R: its principal parts are all ≤ 0 (R is negative
/// semi-definite), so R ≠ 0 exactly when a diagonal component is.
template <int dim>
bool carries_artificial_stress(const ParticlesOf<dim>& p, std::size_t i) {
  if constexpr (dim == 2)
    return p.rxx[i] != 0.0 || p.ryy[i] != 0.0;
  else
    return p.rxx[i] != 0.0 || p.ryy[i] != 0.0 || p.rzz[i] != 0.0;
}

/// R of particle i in space (already divided by ρ²) into p.rxx … p.ryz. A particle whose stress is
/// negative semi-definite by Gershgorin's theorem (every diagonal entry plus the absolute row's
/// off-diagonal entries ≤ 0: a soil under compression with little shear, most of a mass) gets R = 0
/// without a decomposition. Returns whether R ≠ 0.
inline bool set_artificial_stress(ParticlesOf<3>& p, std::size_t i, double epsilon) {
  const double xx = p.sxx[i], yy = p.syy[i], zz = p.szz[i], xy = p.sxy[i], xz = p.sxz[i], yz = p.syz[i];
  const auto zero = [&] {
    p.rxx[i] = p.ryy[i] = p.rzz[i] = p.rxy[i] = p.rxz[i] = p.ryz[i] = 0.0;
    return false;
  };
  if (xx + std::abs(xy) + std::abs(xz) <= 0.0 && yy + std::abs(xy) + std::abs(yz) <= 0.0 &&
      zz + std::abs(xz) + std::abs(yz) <= 0.0)
    return zero();
  Eigen::Matrix3d sigma;
  sigma << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(sigma);
  const Eigen::Vector3d principal = eigen.eigenvalues();
  if (principal.maxCoeff() <= 0.0) return zero();
  const double scale = -epsilon / (p.density[i] * p.density[i]);
  const Eigen::Vector3d r = principal.unaryExpr([&](double s) { return s > 0.0 ? scale * s : 0.0; });
  const Eigen::Matrix3d& v = eigen.eigenvectors();
  const Eigen::Matrix3d R = v * r.asDiagonal() * v.transpose();
  p.rxx[i] = R(0, 0), p.ryy[i] = R(1, 1), p.rzz[i] = R(2, 2);
  p.rxy[i] = R(0, 1), p.rxz[i] = R(0, 2), p.ryz[i] = R(1, 2);
  return carries_artificial_stress(p, i);
}

/// R of particle i in the plane (already divided by ρ²) into p.rxx, p.ryy, p.rxy. A particle without
/// a tensile principal stress, σ_max = (σxx + σyy)/2 + √(((σxx − σyy)/2)² + σxy²) ≤ 0 (most of a
/// soil mass), gets R = 0 without the principal-axes rotation. Returns whether R ≠ 0.
inline bool set_artificial_stress(ParticlesOf<2>& p, std::size_t i, double epsilon) {
  const double sxx = p.sxx[i], syy = p.syy[i], sxy = p.sxy[i];
  const double centre = 0.5 * (sxx + syy), half_difference = 0.5 * (sxx - syy);
  const double radius2 = half_difference * half_difference + sxy * sxy;  // of Mohr's circle
  // σ_max ≤ 0 without the square root: centre ≤ 0 and radius² ≤ centre².
  if (centre <= 0.0 && radius2 <= centre * centre) {
    p.rxx[i] = p.ryy[i] = p.rxy[i] = 0.0;
    return false;
  }
  // Principal stresses centre ± radius and axes without trigonometry: with tan 2θ = 2σxy/(σxx − σyy),
  // cos 2θ = ((σxx − σyy)/2)/radius and sin 2θ = σxy/radius, so c² = (1 + cos 2θ)/2,
  // s² = (1 − cos 2θ)/2 and cs = sin 2θ/2 (θ = 0 for an isotropic stress, radius 0). s1 = centre +
  // radius is the one along θ.
  const double radius = std::sqrt(radius2);
  const double cos2 = radius > 0.0 ? half_difference / radius : 1.0, sin2 = radius > 0.0 ? sxy / radius : 0.0;
  const double cc = 0.5 * (1.0 + cos2), ss = 0.5 * (1.0 - cos2), cs = 0.5 * sin2;
  const double s1 = centre + radius, s2 = centre - radius;
  const double scale = -epsilon / (p.density[i] * p.density[i]);
  const double r1 = s1 > 0.0 ? scale * s1 : 0.0;
  const double r2 = s2 > 0.0 ? scale * s2 : 0.0;
  p.rxx[i] = cc * r1 + ss * r2;
  p.ryy[i] = ss * r1 + cc * r2;
  p.rxy[i] = cs * (r1 - r2);
  return carries_artificial_stress(p, i);
}

/// Fills the artificial stress of every particle, soil and boundary (one thread).
template <int dim>
void compute_artificial_stress(ParticlesOf<dim>& p, double epsilon) {
  for (std::size_t i = 0; i < p.size(); ++i) set_artificial_stress(p, i, epsilon);
}

}  // namespace soilsph::sph
