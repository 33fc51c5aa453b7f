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
  ArtificialStress artificial_stress;  ///< off unless built with its parameters
};

struct Acceleration {
  double x, y;
};

/// What every pair of the momentum equation reads of particle i (particles.h, MomentumSource): σ/ρ²
/// once per particle instead of a division per pair, and a copy of v, ρ, m. After its artificial
/// stress (set_artificial_stress).
inline void set_momentum_source(Particles& p, std::size_t i) {
  const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
  p.momentum_source[i] = {p.sxx[i] * inv_rho2, p.syy[i] * inv_rho2, p.sxy[i] * inv_rho2, p.vx[i], p.vy[i],
                          p.density[i],        p.mass[i],           carries_artificial_stress(p, i)};
}

/// The pair terms of eq 12 for one particle i: what neighbour j contributes to a_i through the pair
/// q (m/s²), from the momentum sources (set_momentum_source) and the artificial stress. One
/// definition for the step's sum (acceleration_of) and for the force each wall's ghosts exert
/// (analysis/boundary_forces.h). In two parts: the stress and viscosity terms, without a branch so
/// that the sum over a row vectorises, and the artificial stress, which needs f^n and acts only
/// where i or j is in tension (a few pairs), summed apart.
class PairAcceleration {
 public:
  PairAcceleration(const Particles& p, const MomentumParams& m, std::size_t i)
      : p_(p),
        i_(i),
        h_(m.smoothing_length),
        eta2_(0.01 * h_ * h_),
        alpha_c_(m.viscosity_alpha * m.sound_speed),
        beta_(m.viscosity_beta),
        art_(m.artificial_stress.enabled()),
        artificial_stress_(m.artificial_stress),
        source_(p.momentum_source.data()),
        self_(p.momentum_source[i]) {}

  /// The terms of σ/ρ² and of the viscosity Π (eq 37) for neighbour j, x_i − x_j = (rx, ry) and
  /// ∇_i W_ij = (gx, gy).
  Acceleration stress_and_viscosity(std::size_t j, double rx, double ry, double gx, double gy) const {
    const MomentumSource& a = self_;
    const MomentumSource& b = source_[j];
    const double v_dot_r = (a.vx - b.vx) * rx + (a.vy - b.vy) * ry;
    // Π = (−α c φ + β φ²)/ρ̄ with φ = h v·r/d, d = r² + η², ρ̄ = (ρ_i + ρ_j)/2, over one division:
    // Π = 2 h v·r (β h v·r − α c d) / (d² (ρ_i + ρ_j)); only approaching pairs (v·r < 0). Evaluated
    // for every pair and multiplied by 0 or 1 rather than branched on or selected, which the
    // compiler would turn back into a branch around the division (d > 0: Π is finite for every pair).
    const double d = rx * rx + ry * ry + eta2_, hv = h_ * v_dot_r;
    const double approaching = v_dot_r < 0.0 ? 1.0 : 0.0;
    const double pi =
        approaching * (2.0 * hv * (beta_ * hv - alpha_c_ * d) / (d * d * (a.density + b.density)));
    const double txx = a.sxx_rho2 + b.sxx_rho2 - pi;
    const double tyy = a.syy_rho2 + b.syy_rho2 - pi;
    const double txy = a.sxy_rho2 + b.sxy_rho2;
    return {b.mass * (txx * gx + txy * gy), b.mass * (txy * gx + tyy * gy)};
  }
  /// Whether the pair with j has an artificial-stress term (R = 0 without tension).
  bool has_artificial_stress(std::size_t j) const { return art_ && (self_.tension || source_[j].tension); }
  /// The artificial-stress term (R_i + R_j) f_ij^n of the pair with j, W_ij = w.
  Acceleration artificial_stress(std::size_t j, double w, double gx, double gy) const {
    const Particles& p = p_;
    const double f = artificial_stress_.weight(w);
    const double txx = f * (p.rxx[i_] + p.rxx[j]), tyy = f * (p.ryy[i_] + p.ryy[j]);
    const double txy = f * (p.rxy[i_] + p.rxy[j]);
    const double mass = source_[j].mass;
    return {mass * (txx * gx + txy * gy), mass * (txy * gx + tyy * gy)};
  }
  /// Both parts.
  Acceleration operator()(const NeighbourList::Pair& q) const {
    Acceleration a = stress_and_viscosity(q.j, q.rx, q.ry, q.gx, q.gy);
    if (has_artificial_stress(q.j)) {
      const Acceleration r = artificial_stress(q.j, q.w, q.gx, q.gy);
      a.x += r.x, a.y += r.y;
    }
    return a;
  }
  /// Any pair of i can have an artificial-stress term.
  bool artificial_stress_enabled() const { return art_; }

 private:
  const Particles& p_;
  std::size_t i_;
  double h_, eta2_, alpha_c_, beta_;
  bool art_;
  const ArtificialStress& artificial_stress_;
  const MomentumSource* source_;
  MomentumSource self_;
};

/// a_i of soil particle i: the pair terms of every neighbour (soil and ghost) and gravity. The stress
/// and viscosity terms in one loop vectorised across the row's pairs, then the few artificial-stress
/// terms, unless no particle is in tension this step (`any_tension` false: none ever is in the shipped
/// D-P scenes, where the scan of every pair for a tensile neighbour was 3 % of the step). Out of line
/// (stages/momentum.cpp), so that the loop is compiled on its own whatever the caller inlines (GCC 12
/// -fopt-info-vec: vectorised with SSE2 and AVX2 alike).
[[gnu::noinline]] Acceleration acceleration_of(const Particles& p, const NeighbourList& nl,
                                                const MomentumParams& m, std::size_t i, bool any_tension);

/// Fills p.ax, p.ay for every soil particle (one thread), after the artificial stress.
inline void compute_acceleration(Particles& p, const NeighbourList& nl, const MomentumParams& m) {
  bool any_tension = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    set_momentum_source(p, i);
    any_tension = any_tension || p.momentum_source[i].tension;
  }
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const Acceleration a = acceleration_of(p, nl, m, i, any_tension);
    p.ax[i] = a.x;
    p.ay[i] = a.y;
  }
}

}  // namespace soilsph::sph
