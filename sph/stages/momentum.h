#pragma once
/// @file
/// The momentum equation (paper eq 12 with the artificial viscosity of eq 36–38):
///   Dv_i^α/Dt = Σ_j m_j (σ_i^{αβ}/ρ_i² + σ_j^{αβ}/ρ_j² − Π_ij δ^{αβ} + (R_i + R_j)^{αβ} f_ij^n) ∂W_ij/∂x_i^β
///   + g^α Π_ij = (−α_Π c̄ φ_ij + β_Π φ_ij²)/ρ̄_ij  when (v_i − v_j)·(x_i − x_j) < 0, else 0, φ_ij = h (v_i −
///   v_j)·(x_i − x_j) / (|x_i − x_j|² + (0.1h)²),
/// with one smoothing length h and one sound speed c for all particles (so h_ij = h, c̄_ij = c), and
/// R the artificial stress (stages/artificial_stress.h). Sums run over soil and boundary neighbours;
/// α, β run over the dimension's axes.
#include <array>
#include <cmath>

#include "sph/geometry/vec3.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/artificial_stress.h"
#include "sph/stages/pair_vectors.h"

namespace soilsph::sph {

template <int dim>
struct MomentumParamsOf {
  double viscosity_alpha = 0.1;   ///< α_Π
  double viscosity_beta = 0.1;    ///< β_Π
  double sound_speed = 0.0;       ///< c (m/s), the elastic P-wave speed (time_step.h)
  double smoothing_length = 0.0;  ///< h (m)
  Vec<dim> gravity = down_gravity();  ///< m/s²
  ArtificialStress artificial_stress;  ///< off unless built with its parameters

  /// −9.81 m/s² along −y, in the plane and in space.
  static Vec<dim> down_gravity() {
    Vec<dim> g{};
    g.y = -9.81;
    return g;
  }
};
using MomentumParams = MomentumParamsOf<2>;

/// a = Dv/Dt of one particle, or one pair's part of it (m/s²).
template <int dim>
using AccelerationOf = std::array<double, dim>;

/// What every pair of the momentum equation reads of particle i (particles.h, MomentumSourceOf):
/// σ/ρ² once per particle instead of a division per pair, and a copy of v, ρ, m. After its
/// artificial stress (set_artificial_stress).
template <int dim>
void set_momentum_source(ParticlesOf<dim>& p, std::size_t i) {
  const double inv_rho2 = 1.0 / (p.density[i] * p.density[i]);
  if constexpr (dim == 2) {
    p.momentum_source[i] = {p.sxx[i] * inv_rho2, p.syy[i] * inv_rho2, p.sxy[i] * inv_rho2, p.vx[i], p.vy[i],
                            p.density[i],        p.mass[i],           carries_artificial_stress(p, i)};
  } else {
    MomentumSourceOf<3>& s = p.momentum_source[i];
    const auto stress = stress_arrays(std::as_const(p));
    for (int k = 0; k < 6; ++k) s.stress_rho2[k] = (*stress[k])[i] * inv_rho2;
    s.v = {p.vx[i], p.vy[i], p.vz[i]};
    s.density = p.density[i], s.mass = p.mass[i], s.tension = carries_artificial_stress(p, i);
  }
}

/// The pair terms of eq 12 for one particle i: what neighbour j contributes to a_i through the pair
/// (m/s²), from the momentum sources (set_momentum_source) and the artificial stress. One
/// definition for the step's sum (acceleration_of) and for the force each wall's ghosts exert
/// (analysis/boundary_forces.h). In two parts: the stress and viscosity terms, without a branch so
/// that the sum over a row vectorises, and the artificial stress, which needs f^n and acts only
/// where i or j is in tension (a few pairs), summed apart.
template <int dim>
class PairAccelerationOf {
 public:
  using Vector = std::array<double, dim>;

  PairAccelerationOf(const ParticlesOf<dim>& p, const MomentumParamsOf<dim>& m, std::size_t i)
      : i_(i),
        h_(m.smoothing_length),
        eta2_(0.01 * h_ * h_),
        alpha_c_(m.viscosity_alpha * m.sound_speed),
        beta_(m.viscosity_beta),
        art_(m.artificial_stress.enabled()),
        artificial_stress_(m.artificial_stress),
        source_(p.momentum_source.data()),
        self_(p.momentum_source[i]),
        artificial_(artificial_stress_arrays(p)) {}

  /// The terms of σ/ρ² and of the viscosity Π (eq 37) for neighbour j in the plane, x_i − x_j =
  /// (rx, ry), ∇_i W_ij = (gx, gy): in scalars, the form whose row sum GCC vectorises across pairs
  /// (MomentumSourceOf<2>).
  struct Plane {
    double x, y;
  };
  Plane stress_and_viscosity(std::size_t j, double rx, double ry, double gx, double gy) const
    requires(dim == 2)
  {
    const MomentumSourceOf<2>& a = self_;
    const MomentumSourceOf<2>& b = source_[j];
    const double v_dot_r = (a.vx - b.vx) * rx + (a.vy - b.vy) * ry;
    const double d = rx * rx + ry * ry + eta2_, hv = h_ * v_dot_r;
    const double approaching = v_dot_r < 0.0 ? 1.0 : 0.0;
    const double pi =
        approaching * (2.0 * hv * (beta_ * hv - alpha_c_ * d) / (d * d * (a.density + b.density)));
    const double txx = a.sxx_rho2 + b.sxx_rho2 - pi;
    const double tyy = a.syy_rho2 + b.syy_rho2 - pi;
    const double txy = a.sxy_rho2 + b.sxy_rho2;
    return {b.mass * (txx * gx + txy * gy), b.mass * (txy * gx + tyy * gy)};
  }

  /// The same in space, x_i − x_j = r and ∇_i W_ij = g.
  Vector stress_and_viscosity(std::size_t j, const Vector& r, const Vector& g) const
    requires(dim == 3)
  {
    const MomentumSourceOf<dim>& a = self_;
    const MomentumSourceOf<dim>& b = source_[j];
    double v_dot_r = (a.v[0] - b.v[0]) * r[0];
    for (int k = 1; k < dim; ++k) v_dot_r += (a.v[k] - b.v[k]) * r[k];
    // Π = (−α c φ + β φ²)/ρ̄ with φ = h v·r/d, d = r² + η², ρ̄ = (ρ_i + ρ_j)/2, over one division:
    // Π = 2 h v·r (β h v·r − α c d) / (d² (ρ_i + ρ_j)); only approaching pairs (v·r < 0). Evaluated
    // for every pair and multiplied by 0 or 1 rather than branched on or selected, which the
    // compiler would turn back into a branch around the division (d > 0: Π is finite for every pair).
    double d = r[0] * r[0];
    for (int k = 1; k < dim; ++k) d += r[k] * r[k];
    d += eta2_;
    const double hv = h_ * v_dot_r;
    const double approaching = v_dot_r < 0.0 ? 1.0 : 0.0;
    const double pi =
        approaching * (2.0 * hv * (beta_ * hv - alpha_c_ * d) / (d * d * (a.density + b.density)));
    std::array<double, kSymmetricComponents<dim>> t;
    for (int k = 0; k < dim; ++k) t[k] = a.stress_rho2[k] + b.stress_rho2[k] - pi;
    for (int k = dim; k < kSymmetricComponents<dim>; ++k) t[k] = a.stress_rho2[k] + b.stress_rho2[k];
    return contracted(b.mass, t, g);
  }
  /// Whether the pair with j has an artificial-stress term (R = 0 without tension).
  bool has_artificial_stress(std::size_t j) const { return art_ && (self_.tension || source_[j].tension); }
  /// The artificial-stress term (R_i + R_j) f_ij^n of the pair with j, W_ij = w.
  Vector artificial_stress(std::size_t j, double w, const Vector& g) const {
    const double f = artificial_stress_.weight(w);
    std::array<double, kSymmetricComponents<dim>> t;
    for (int k = 0; k < kSymmetricComponents<dim>; ++k) t[k] = f * ((*artificial_[k])[i_] + (*artificial_[k])[j]);
    return contracted(source_[j].mass, t, g);
  }
  /// Both parts.
  Vector operator()(const PairVectors<dim>& q) const {
    Vector a;
    if constexpr (dim == 2) {
      const Plane b = stress_and_viscosity(q.j, q.r[0], q.r[1], q.g[0], q.g[1]);
      a = {b.x, b.y};
    } else {
      a = stress_and_viscosity(q.j, q.r, q.g);
    }
    if (has_artificial_stress(q.j)) {
      const Vector r = artificial_stress(q.j, q.w, q.g);
      for (int k = 0; k < dim; ++k) a[k] += r[k];
    }
    return a;
  }
  /// Any pair of i can have an artificial-stress term.
  bool artificial_stress_enabled() const { return art_; }

 private:
  /// m t·g for the symmetric tensor t (symmetric_index order).
  static Vector contracted(double mass, const std::array<double, kSymmetricComponents<dim>>& t, const Vector& g) {
    Vector a;
    for (int row = 0; row < dim; ++row) {
      double s = t[symmetric_index<dim>(row, 0)] * g[0];
      for (int col = 1; col < dim; ++col) s += t[symmetric_index<dim>(row, col)] * g[col];
      a[row] = mass * s;
    }
    return a;
  }
  static std::array<const std::vector<double>*, kSymmetricComponents<dim>> artificial_stress_arrays(
      const ParticlesOf<dim>& p) {
    if constexpr (dim == 2)
      return {&p.rxx, &p.ryy, &p.rxy};
    else
      return {&p.rxx, &p.ryy, &p.rzz, &p.rxy, &p.rxz, &p.ryz};
  }

  std::size_t i_;
  double h_, eta2_, alpha_c_, beta_;
  bool art_;
  const ArtificialStress& artificial_stress_;
  const MomentumSourceOf<dim>* source_;
  MomentumSourceOf<dim> self_;
  std::array<const std::vector<double>*, kSymmetricComponents<dim>> artificial_;
};
using PairAcceleration = PairAccelerationOf<2>;

/// a_i of soil particle i: the pair terms of every neighbour (soil and ghost) and gravity. The stress
/// and viscosity terms in one loop vectorised across the row's pairs, then the few artificial-stress
/// terms, unless no particle is in tension this step (`any_tension` false: none ever is in the shipped
/// D-P scenes, where the scan of every pair for a tensile neighbour was 3 % of the step). Out of line
/// (stages/momentum.cpp, instantiated for 2 and 3 dimensions), so that the loop is compiled on its
/// own whatever the caller inlines (GCC 12 -fopt-info-vec: vectorised with SSE2 and AVX2 alike).
[[gnu::noinline]] AccelerationOf<2> acceleration_of(const ParticlesOf<2>& p, const PairList<2>& nl,
                                                    const MomentumParamsOf<2>& m, std::size_t i, bool any_tension);
[[gnu::noinline]] AccelerationOf<3> acceleration_of(const ParticlesOf<3>& p, const PairList<3>& nl,
                                                    const MomentumParamsOf<3>& m, std::size_t i, bool any_tension);

/// The acceleration arrays of the soil (ax, ay[, az]).
template <int dim>
std::array<std::vector<double>*, dim> acceleration_arrays(ParticlesOf<dim>& p) {
  if constexpr (dim == 2)
    return {&p.ax, &p.ay};
  else
    return {&p.ax, &p.ay, &p.az};
}

/// Fills the acceleration of every soil particle (one thread), after the artificial stress.
template <int dim>
void compute_acceleration(ParticlesOf<dim>& p, const PairList<dim>& nl, const MomentumParamsOf<dim>& m) {
  bool any_tension = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    set_momentum_source(p, i);
    any_tension = any_tension || p.momentum_source[i].tension;
  }
  const auto acceleration = acceleration_arrays(p);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const AccelerationOf<dim> a = acceleration_of(p, nl, m, i, any_tension);
    for (int k = 0; k < dim; ++k) (*acceleration[k])[i] = a[k];
  }
}

}  // namespace soilsph::sph
