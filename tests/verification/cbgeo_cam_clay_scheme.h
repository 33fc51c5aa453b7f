#pragma once
/// @file
/// CB-Geo mpm's Modified Cam-Clay stress update (one backward-Euler step per strain increment),
/// written out from its definition so that a test can (1) reproduce CB-Geo's published numbers, which
/// shows that the definitions below are CB-Geo's, and (2) apply the same update to the increment
/// split into many parts, which converges to the rate equations and so measures the one-step error
/// of CB-Geo's numbers before they are compared with soilsph.
///
/// Source: cb-geo/mpm, include/materials/modified_cam_clay.tcc (compute_elastic_tensor,
/// compute_yield_state, compute_dg_dpc, compute_stress; stored version
/// 0f4dc2dba4b18cbeb814e21e7c474558bf229454, without bonding, subloading or three invariants).
/// With p, p_c compression-positive and tension-positive stresses and strains, one increment Δε is
///   K = (1+e) p_n/κ, G = 3K(1−2ν)/(2(1+ν))  (e and p_n at the increment's start: frozen)
///   σ_tr = σ_n + D Δε;  elastic when f_tr = (q_tr/M)² + p_tr (p_tr − p_c,n) ≤ 0, else with Δφ ≥ 0
///   p   = (p_tr + K Δφ p_c) / (1 + 2K Δφ)                     (compute_stress, "Update mean pressure")
///   q   = q_tr / (1 + 6G Δφ/M²)                                (Equation 3.10b there)
///   p_c = p_c,n exp(υ Δφ (2p − p_c)),  υ = (1+e)/(λ−κ)        (compute_dg_dpc)
///   f(p, q, p_c) = 0, σ = q n_tr − p I (n_tr = dev σ_tr / q_tr);  e += (1+e0) tr Δε.
#include <Eigen/Dense>
#include <cmath>

#include "verification/closed_form/gsl_numerics.h"

namespace soilsph::test {

struct CbGeoCamClay {
  double M, lambda, kappa, nu, e0;
};

struct CbGeoPoint {
  Eigen::Vector3d stress;  ///< principal (xx, yy, zz), tension-positive, Pa
  double pc;               ///< Pa
  double e;                ///< void ratio
};

/// One increment `d_strain` (principal, tension-positive) of CB-Geo's update.
inline CbGeoPoint cbgeo_step(const CbGeoCamClay& m, const CbGeoPoint& n, const Eigen::Vector3d& d_strain) {
  const double p_n = -n.stress.sum() / 3.0;
  const double K = (1.0 + n.e) / m.kappa * p_n, G = 3.0 * K * (1.0 - 2.0 * m.nu) / (2.0 * (1.0 + m.nu));
  const double d_mean = d_strain.sum() / 3.0;
  const Eigen::Vector3d trial =
      n.stress + 2.0 * G * (d_strain.array() - d_mean).matrix() + Eigen::Vector3d::Constant(3.0 * K * d_mean);
  const double p_tr = -trial.sum() / 3.0;
  const Eigen::Vector3d dev = (trial.array() + p_tr).matrix();
  const double q_tr = std::sqrt(1.5 * dev.squaredNorm());
  const double e = n.e + (1.0 + m.e0) * d_strain.sum();
  if (std::pow(q_tr / m.M, 2) + p_tr * (p_tr - n.pc) <= 0.0) return {trial, n.pc, e};
  const double upsilon = (1.0 + n.e) / (m.lambda - m.kappa);
  // p_c at Δφ: the root of p_c,n exp(υ Δφ (2p_tr − p_c)/(1 + 2KΔφ)) − p_c (2p − p_c written with p_tr).
  const auto pc_at = [&](double dphi) {
    return verification::find_root(
        [&](double pc) {
          return n.pc * std::exp(upsilon * dphi * (2.0 * p_tr - pc) / (1.0 + 2.0 * K * dphi)) - pc;
        },
        0.5 * n.pc, 10.0 * n.pc);
  };
  const auto p_at = [&](double dphi, double pc) { return (p_tr + K * dphi * pc) / (1.0 + 2.0 * K * dphi); };
  const auto q_at = [&](double dphi) { return q_tr / (1.0 + 6.0 * G * dphi / (m.M * m.M)); };
  const double dphi = verification::find_root(
      [&](double dphi) {
        const double pc = pc_at(dphi), p = p_at(dphi, pc);
        return std::pow(q_at(dphi) / m.M, 2) + p * (p - pc);
      },
      0.0, 1.0 / K);
  const double pc = pc_at(dphi);
  const Eigen::Vector3d stress = (q_at(dphi) / q_tr) * dev - Eigen::Vector3d::Constant(p_at(dphi, pc));
  return {stress, pc, e};
}

/// The increment `d_strain` in `parts` equal parts.
inline CbGeoPoint cbgeo_update(const CbGeoCamClay& m, CbGeoPoint point, const Eigen::Vector3d& d_strain,
                               int parts) {
  for (int k = 0; k < parts; ++k) point = cbgeo_step(m, point, d_strain / parts);
  return point;
}

}  // namespace soilsph::test
