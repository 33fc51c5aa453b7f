#pragma once
/// @file
/// The mirror of the soil across a planar wall, as pure functions: the 3D form of the ghost rules
/// of stages/boundaries.h (which gives their derivation and sign conventions in 2D). With n the
/// unit normal towards the soil, v_w the wall's velocity, Δv = v̄ − v_w the soil's (kernel-averaged)
/// velocity relative to the wall and Δv_t = Δv − (Δv·n) n its tangential slip vector:
///   position  x_b = x − 2 ((x − x_w)·n) n
///   velocity  v_b = v̄ − 2 (Δv·n) n − 2 s Δv_t          (s = 1 sticking, 0 sliding)
///   stress    σ_b = σ̄ + c⊗n + n⊗c,  c = 2 (τ − τ̄)
/// where τ̄ = σ̄n − (n·σ̄n) n is the soil's shear traction on the wall (a vector in its plane) and τ
/// the wall's: then σ_b keeps σ̄'s normal stress n·σ̄n and in-plane stresses, and its shear traction
/// is 2τ − τ̄, so that the average across the wall is τ. In 2D, t = (−n_y, n_x), these are the
/// 2D formulas with τ = σ_nt t and Δv_t = (Δv·t) t. The wall's shear traction:
///  - free slip, μ = 0 (a symmetry plane is one): τ = 0, s = 0;
///  - no slip, μ = ∞: τ = τ̄, s = 1 (Adami et al. 2012, J. Comput. Phys. 231:7057);
///  - frictional, μ = tan δ, Coulomb's law |τ| ≤ μ σ'_n, σ'_n = max(−n·σ̄n, 0): while the soil
///    slips (|Δv_t| > the stick-slip speed) kinetic friction against the slip vector,
///    τ = μ σ'_n Δv_t / |Δv_t|, s = 0; else it sticks, τ = τ̄, s = 1, while |τ̄| < μ σ'_n, and
///    slides with τ = μ σ'_n τ̄ / |τ̄|, s = 0, beyond.
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// The mirror image of p across the plane through `on_plane` with unit normal n.
inline Vec3 mirror_point(Vec3 p, Vec3 on_plane, Vec3 n) {
  return p - (2.0 * dot(p - on_plane, n)) * n;
}

/// The ghost's velocity from the soil's v̄, the wall's v_w and the stick flag s (above).
inline Vec3 ghost_velocity(Vec3 soil, Vec3 wall, Vec3 n, double stick) {
  const Vec3 dv = soil - wall;
  const double dn = dot(dv, n);
  const Vec3 slip = dv - dn * n;
  return soil - (2.0 * dn) * n - (2.0 * stick) * slip;
}

/// The wall's shear traction τ (in its plane) and the stick flag s.
struct WallShear {
  Vec3 traction;
  double stick;
};

/// τ and s of a wall of friction coefficient μ (0 free slip, +∞ no slip) under the soil's
/// tension-positive stress σ̄ and relative velocity Δv = v̄ − v_w; the soil sticks below the slip
/// speed `stick_slip` (m/s).
inline WallShear wall_shear(const Eigen::Matrix3d& stress, Vec3 n, Vec3 relative_velocity, double mu,
                            double stick_slip) {
  const Eigen::Vector3d nn{n.x, n.y, n.z}, t_full = stress * nn;
  const double s_nn = nn.dot(t_full);
  const Eigen::Vector3d shear = t_full - s_nn * nn;
  const Vec3 tau_soil{shear.x(), shear.y(), shear.z()};
  const double inf = std::numeric_limits<double>::infinity();
  if (mu == inf) return {tau_soil, 1.0};
  const double limit = mu * std::max(-s_nn, 0.0);
  if (limit <= 0.0) return {{}, 0.0};  // free slip, or a wall in tension
  const Vec3 slip = relative_velocity - dot(relative_velocity, n) * n;
  if (norm(slip) > stick_slip) return {(limit / norm(slip)) * slip, 0.0};
  const double demanded = norm(tau_soil);
  if (demanded < limit) return {tau_soil, 1.0};
  return {(limit / demanded) * tau_soil, 0.0};
}

/// The ghost's stress σ_b = σ̄ + c⊗n + n⊗c, c = 2 (τ − τ̄) (above).
inline Eigen::Matrix3d ghost_stress(const Eigen::Matrix3d& stress, Vec3 n, Vec3 wall_traction) {
  const Eigen::Vector3d nn{n.x, n.y, n.z}, t_full = stress * nn;
  const Eigen::Vector3d tau_soil = t_full - nn.dot(t_full) * nn;
  const Eigen::Vector3d c =
      2.0 * (Eigen::Vector3d{wall_traction.x, wall_traction.y, wall_traction.z} - tau_soil);
  return stress + c * nn.transpose() + nn * c.transpose();
}

}  // namespace soilsph::sph
