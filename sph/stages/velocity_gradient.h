#pragma once
/// @file
/// The SPH velocity gradient (paper eq 23):
///   ∂v^α/∂x^β |_i = Σ_j (m_j/ρ_j) (v_j^α − v_i^α) ∂W_ij/∂x_i^β,
/// over soil and boundary neighbours; the strain rate is its symmetric part and the spin rate
/// ω̇ = ½(∂v^α/∂x^β − ∂v^β/∂x^α) its skew part (plane strain: no z components).
///
/// For v = A x the sum gives A M with the kernel moment M^{γβ} = Σ_j (m_j/ρ_j)(x_j − x_i)^γ ∂W_ij/∂x_i^β,
/// which is I only for a full, regular neighbourhood: on a lattice with h = 1.3Δp it is 1.0105 I
/// (a 1 % error), and at a free surface it falls to about ½ I. The optional kernel-gradient correction
/// (Randles & Libersky 1996; Bonet & Lok 1999) multiplies by M⁻¹ so that every linear field is
/// differentiated exactly ([numerics] velocity_gradient_correction, default off: the paper's eq 23).
/// Where M is nearly singular (an isolated particle, det M < 0.1) the uncorrected sum is kept.
#include <span>

#include "constitutive/tensor.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// L = ∂v^α/∂x^β of one particle (lxy = ∂vx/∂y).
struct VelocityGradient {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;

  /// Strain increment ε̇Δt, ε̇ = ½(L + Lᵀ), as a 3×3 tensor (ε̇_zz = 0, plane strain). Built from
  /// scaled scalars in one initialiser rather than as a zeroed matrix set entry by entry and then
  /// scaled: GCC 12 compiled that into 8-byte stores read back by 16-byte loads, a store-forwarding
  /// stall that took 40 % of the SPH stress update's own samples.
  Mat3 strain_increment(double dt) const {
    const double a = xx * dt, b = (0.5 * (xy + yx)) * dt, c = yy * dt;
    Mat3 d;
    d << a, b, 0.0, b, c, 0.0, 0.0, 0.0, 0.0;
    return d;
  }
  /// Spin increment ω̇Δt, ω̇ = ½(L − Lᵀ) (eq 23).
  Mat3 spin_increment(double dt) const {
    const double w = (0.5 * (xy - yx)) * dt;
    Mat3 s;
    s << 0.0, w, 0.0, -w, 0.0, 0.0, 0.0, 0.0, 0.0;
    return s;
  }
};

/// Eq 23 at soil particle i and, in the same pass over its pairs, the continuity equation's
/// Dρ_i/Dt = Σ_j m_j (v_i − v_j)·∇_i W_ij (eq 11, stages/continuity.h), with the velocities (vx, vy).
struct KinematicRates {
  VelocityGradient L;
  double density_rate;
};
/// `volume_of(j)` gives m_j/ρ_j.
template <class Volume>
KinematicRates kinematic_rates_with(const Particles& p, const NeighbourList& nl, std::size_t i,
                                    std::span<const double> vx, std::span<const double> vy,
                                    Volume&& volume_of, bool corrected) {
  VelocityGradient L;
  double rate = 0.0;
  double mxx = 0.0, mxy = 0.0, myx = 0.0, myy = 0.0;  // kernel moment M (x_j − x_i = −r)
  nl.for_each_pair(i, [&](const NeighbourList::Pair& q) {
    const std::size_t j = q.j;
    const double volume = volume_of(j);
    const double dvx = vx[j] - vx[i], dvy = vy[j] - vy[i];
    L.xx += volume * dvx * q.gx;
    L.xy += volume * dvx * q.gy;
    L.yx += volume * dvy * q.gx;
    L.yy += volume * dvy * q.gy;
    rate -= p.mass[j] * (dvx * q.gx + dvy * q.gy);
    if (corrected) {
      mxx -= volume * q.rx * q.gx;
      mxy -= volume * q.rx * q.gy;
      myx -= volume * q.ry * q.gx;
      myy -= volume * q.ry * q.gy;
    }
  });
  const double det = mxx * myy - mxy * myx;
  if (corrected && det > 0.1) {  // L ← L M⁻¹
    const double ixx = myy / det, ixy = -mxy / det, iyx = -myx / det, iyy = mxx / det;
    L = {L.xx * ixx + L.xy * iyx, L.xx * ixy + L.xy * iyy, L.yx * ixx + L.yy * iyx, L.yx * ixy + L.yy * iyy};
  }
  return {L, rate};
}

/// m/ρ of particle i, read by every pair of eq 23.
inline double particle_volume(const Particles& p, std::size_t i) { return p.mass[i] / p.density[i]; }

/// With `volume` holding particle_volume of every particle: one division per particle, not per pair.
inline KinematicRates kinematic_rates_of(const Particles& p, const NeighbourList& nl, std::size_t i,
                                         std::span<const double> vx, std::span<const double> vy,
                                         std::span<const double> volume, bool corrected) {
  return kinematic_rates_with(p, nl, i, vx, vy, [&](std::size_t j) { return volume[j]; }, corrected);
}
/// The same, each volume computed where it is read.
inline KinematicRates kinematic_rates_of(const Particles& p, const NeighbourList& nl, std::size_t i,
                                         std::span<const double> vx, std::span<const double> vy,
                                         bool corrected) {
  return kinematic_rates_with(p, nl, i, vx, vy, [&](std::size_t j) { return particle_volume(p, j); },
                              corrected);
}

/// Fills p.lxx, p.lxy, p.lyx, p.lyy for every soil particle from p.vx, p.vy (orphaned OpenMP loop).
inline void compute_velocity_gradient(Particles& p, const NeighbourList& nl, bool corrected = false) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const VelocityGradient L = kinematic_rates_of(p, nl, i, p.vx, p.vy, corrected).L;
    p.lxx[i] = L.xx, p.lxy[i] = L.xy, p.lyx[i] = L.yx, p.lyy[i] = L.yy;
  }
}

/// The stored gradient of soil particle i (filled by compute_velocity_gradient).
inline VelocityGradient stored_velocity_gradient(const Particles& p, std::size_t i) {
  return {p.lxx[i], p.lxy[i], p.lyx[i], p.lyy[i]};
}

}  // namespace soilsph::sph
