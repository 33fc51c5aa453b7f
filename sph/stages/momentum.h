#pragma once
/// @file
/// The momentum equation (paper eq 12 with the artificial viscosity of eq 36–38):
///   Dv_i^α/Dt = Σ_j m_j (σ_i^{αβ}/ρ_i² + σ_j^{αβ}/ρ_j² − Π_ij δ^{αβ} + (R_i + R_j)^{αβ} f_ij^n) ∂W_ij/∂x_i^β
///   + g^α Π_ij = (−α_Π c̄ φ_ij + β_Π φ_ij²)/ρ̄_ij  when (v_i − v_j)·(x_i − x_j) < 0, else 0, φ_ij = h (v_i −
///   v_j)·(x_i − x_j) / (|x_i − x_j|² + (0.1h)²),
/// with one smoothing length h and one sound speed c for all particles (so h_ij = h, c̄_ij = c), and
/// R the artificial stress (stages/artificial_stress.h). Sums run over soil and boundary neighbours.
#include <cmath>

#include "sph/geometry/vec2.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/artificial_stress.h"

namespace soilsph::sph {

struct MomentumParams {
  double viscosity_alpha = 0.1;   ///< α_Π
  double viscosity_beta = 0.1;    ///< β_Π
  double sound_speed = 0.0;       ///< c (m/s), the elastic P-wave speed (time_step.h)
  double smoothing_length = 0.0;  ///< h (m)
  Vec2 gravity{0.0, -9.81};       ///< m/s²
  ArtificialStress artificial_stress;
};

struct Acceleration {
  double x, y;
};

/// σ/ρ² of particle i, which every pair of the momentum equation reads (once per particle instead
/// of a division per pair).
inline void set_stress_over_density2(Particles& p, std::size_t i) {
  const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
  p.sxx_rho2[i] = p.sxx[i] * inv_rho2, p.syy_rho2[i] = p.syy[i] * inv_rho2,
  p.sxy_rho2[i] = p.sxy[i] * inv_rho2;
}

/// The pair terms of eq 12 for one particle i: what neighbour j contributes to a_i through the pair
/// q (m/s²), from the current σ/ρ² (set_stress_over_density2), artificial stress, density and
/// velocity (p.vx, p.vy). One definition for the step's sum (acceleration_of) and for the force each
/// wall's ghosts exert (analysis/boundary_forces.h).
class PairAcceleration {
 public:
  PairAcceleration(const Particles& p, const MomentumParams& m, std::size_t i)
      : p_(p),
        m_(m),
        i_(i),
        h_(m.smoothing_length),
        eta2_(0.01 * h_ * h_),
        art_(m.artificial_stress.enabled),
        inv_w_dp_(1.0 / m.artificial_stress.w_at_spacing),
        n_exp_(m.artificial_stress.exponent),
        sxx_i_(p.sxx_rho2[i]),
        syy_i_(p.syy_rho2[i]),
        sxy_i_(p.sxy_rho2[i]),
        has_tension_i_(p.rxx[i] != 0.0 || p.ryy[i] != 0.0) {}

  Acceleration operator()(const NeighbourList::Pair& q) const {
    const Particles& p = p_;
    const std::size_t i = i_, j = q.j;
    double txx = sxx_i_ + p.sxx_rho2[j];
    double tyy = syy_i_ + p.syy_rho2[j];
    double txy = sxy_i_ + p.sxy_rho2[j];
    const double v_dot_r = (p.vx[i] - p.vx[j]) * q.rx + (p.vy[i] - p.vy[j]) * q.ry;
    if (v_dot_r < 0.0) {  // eq 37: only approaching pairs
      const double phi = h_ * v_dot_r / (q.rx * q.rx + q.ry * q.ry + eta2_);
      const double pi = (-m_.viscosity_alpha * m_.sound_speed * phi + m_.viscosity_beta * phi * phi) /
                        (0.5 * (p.density[i] + p.density[j]));
      txx -= pi;
      tyy -= pi;
    }
    if (art_ && (has_tension_i_ || p.rxx[j] != 0.0 || p.ryy[j] != 0.0)) {  // R = 0 without tension
      const double f = std::pow(q.w * inv_w_dp_, n_exp_);
      txx += f * (p.rxx[i] + p.rxx[j]);
      tyy += f * (p.ryy[i] + p.ryy[j]);
      txy += f * (p.rxy[i] + p.rxy[j]);
    }
    return {p.mass[j] * (txx * q.gx + txy * q.gy), p.mass[j] * (txy * q.gx + tyy * q.gy)};
  }

 private:
  const Particles& p_;
  const MomentumParams& m_;
  std::size_t i_;
  double h_, eta2_;
  bool art_;
  double inv_w_dp_, n_exp_;
  double sxx_i_, syy_i_, sxy_i_;
  bool has_tension_i_;
};

/// a_i of soil particle i: the pair terms of every neighbour (soil and ghost) and gravity.
inline Acceleration acceleration_of(const Particles& p, const NeighbourList& nl, const MomentumParams& m,
                                    std::size_t i) {
  const PairAcceleration term(p, m, i);
  double ax = 0.0, ay = 0.0;
  nl.for_each_pair(i, [&](const NeighbourList::Pair& q) {
    const Acceleration a = term(q);
    ax += a.x;
    ay += a.y;
  });
  return {ax + m.gravity.x, ay + m.gravity.y};
}

/// Fills p.ax, p.ay for every soil particle (orphaned OpenMP loops).
inline void compute_acceleration(Particles& p, const NeighbourList& nl, const MomentumParams& m) {
  const auto all = static_cast<std::ptrdiff_t>(p.size()), n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < all; ++s) set_stress_over_density2(p, static_cast<std::size_t>(s));
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const Acceleration a = acceleration_of(p, nl, m, i);
    p.ax[i] = a.x;
    p.ay[i] = a.y;
  }
}

}  // namespace soilsph::sph
