#pragma once
/// @file
/// The continuity equation in SPH form (paper eq 11):
///   Dρ_i/Dt = Σ_j m_j (v_i − v_j) · ∇_i W_ij,
/// over soil and boundary neighbours (the ghosts' mirrored velocity keeps the walls impermeable).
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// Fills p.density_rate for every soil particle.
inline void compute_density_rate(Particles& p, const NeighbourList& nl) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    double rate = 0.0;
    for (std::size_t k = nl.begin(i); k < nl.end(i); ++k) {
      const auto j = static_cast<std::size_t>(nl.neighbour[k]);
      rate += p.mass[j] * ((p.vx[i] - p.vx[j]) * nl.gx[k] + (p.vy[i] - p.vy[j]) * nl.gy[k]);
    }
    p.density_rate[i] = rate;
  }
}

}  // namespace soilsph::sph
