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

  /// Strain rate ε̇ = ½(L + Lᵀ) as a 3×3 tensor (ε̇_zz = 0, plane strain).
  Mat3 strain_rate() const {
    const double shear = 0.5 * (xy + yx);
    Mat3 d = Mat3::Zero();
    d(0, 0) = xx, d(1, 1) = yy, d(0, 1) = d(1, 0) = shear;
    return d;
  }
  /// Spin rate ω̇ = ½(L − Lᵀ) (eq 23).
  Mat3 spin_rate() const {
    const double w = 0.5 * (xy - yx);
    Mat3 s = Mat3::Zero();
    s(0, 1) = w, s(1, 0) = -w;
    return s;
  }
};

/// Eq 23 at soil particle i with the velocities (vx, vy); `corrected` applies M⁻¹.
inline VelocityGradient velocity_gradient_of(const Particles& p, const NeighbourList& nl, std::size_t i,
                                             std::span<const double> vx, std::span<const double> vy,
                                             bool corrected) {
  VelocityGradient L;
  double mxx = 0.0, mxy = 0.0, myx = 0.0, myy = 0.0;  // kernel moment M (x_j − x_i = −r)
  for (std::size_t k = nl.begin(i); k < nl.end(i); ++k) {
    const auto j = static_cast<std::size_t>(nl.neighbour[k]);
    const double volume = p.mass[j] / p.density[j];
    const double dvx = volume * (vx[j] - vx[i]), dvy = volume * (vy[j] - vy[i]);
    L.xx += dvx * nl.gx[k];
    L.xy += dvx * nl.gy[k];
    L.yx += dvy * nl.gx[k];
    L.yy += dvy * nl.gy[k];
    if (corrected) {
      mxx -= volume * nl.rx[k] * nl.gx[k];
      mxy -= volume * nl.rx[k] * nl.gy[k];
      myx -= volume * nl.ry[k] * nl.gx[k];
      myy -= volume * nl.ry[k] * nl.gy[k];
    }
  }
  const double det = mxx * myy - mxy * myx;
  if (corrected && det > 0.1) {  // L ← L M⁻¹
    const double ixx = myy / det, ixy = -mxy / det, iyx = -myx / det, iyy = mxx / det;
    return {L.xx * ixx + L.xy * iyx, L.xx * ixy + L.xy * iyy, L.yx * ixx + L.yy * iyx, L.yx * ixy + L.yy * iyy};
  }
  return L;
}

/// Fills p.lxx, p.lxy, p.lyx, p.lyy for every soil particle from p.vx, p.vy (orphaned OpenMP loop).
inline void compute_velocity_gradient(Particles& p, const NeighbourList& nl, bool corrected = false) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const VelocityGradient L = velocity_gradient_of(p, nl, i, p.vx, p.vy, corrected);
    p.lxx[i] = L.xx, p.lxy[i] = L.xy, p.lyx[i] = L.yx, p.lyy[i] = L.yy;
  }
}

/// The stored gradient of soil particle i (filled by compute_velocity_gradient).
inline VelocityGradient stored_velocity_gradient(const Particles& p, std::size_t i) {
  return {p.lxx[i], p.lxy[i], p.lyx[i], p.lyy[i]};
}

}  // namespace soilsph::sph
