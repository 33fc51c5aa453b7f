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
#include "constitutive/tensor.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// Fills p.lxx, p.lxy, p.lyx, p.lyy (lxy = ∂vx/∂y) for every soil particle; `corrected` applies M⁻¹.
inline void compute_velocity_gradient(Particles& p, const NeighbourList& nl, bool corrected = false) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    double lxx = 0.0, lxy = 0.0, lyx = 0.0, lyy = 0.0;
    double mxx = 0.0, mxy = 0.0, myx = 0.0, myy = 0.0;  // kernel moment M (x_j − x_i = −r)
    for (std::size_t k = nl.begin(i); k < nl.end(i); ++k) {
      const auto j = static_cast<std::size_t>(nl.neighbour[k]);
      const double volume = p.mass[j] / p.density[j];
      const double dvx = volume * (p.vx[j] - p.vx[i]), dvy = volume * (p.vy[j] - p.vy[i]);
      lxx += dvx * nl.gx[k];
      lxy += dvx * nl.gy[k];
      lyx += dvy * nl.gx[k];
      lyy += dvy * nl.gy[k];
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
      const double cxx = lxx * ixx + lxy * iyx, cxy = lxx * ixy + lxy * iyy;
      const double cyx = lyx * ixx + lyy * iyx, cyy = lyx * ixy + lyy * iyy;
      lxx = cxx, lxy = cxy, lyx = cyx, lyy = cyy;
    }
    p.lxx[i] = lxx, p.lxy[i] = lxy, p.lyx[i] = lyx, p.lyy[i] = lyy;
  }
}

/// Strain rate ε̇ = ½(L + Lᵀ) of soil particle i as a 3×3 tensor (ε̇_zz = 0, plane strain).
inline Mat3 strain_rate(const Particles& p, std::size_t i) {
  const double shear = 0.5 * (p.lxy[i] + p.lyx[i]);
  Mat3 d = Mat3::Zero();
  d(0, 0) = p.lxx[i], d(1, 1) = p.lyy[i], d(0, 1) = d(1, 0) = shear;
  return d;
}

/// Spin rate ω̇ = ½(L − Lᵀ) of soil particle i (eq 23).
inline Mat3 spin_rate(const Particles& p, std::size_t i) {
  const double w = 0.5 * (p.lxy[i] - p.lyx[i]);
  Mat3 s = Mat3::Zero();
  s(0, 1) = w, s(1, 0) = -w;
  return s;
}

}  // namespace soilsph::sph
