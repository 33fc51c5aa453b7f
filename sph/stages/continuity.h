#pragma once
/// @file
/// The continuity equation in SPH form (paper eq 11):
///   Dρ_i/Dt = Σ_j m_j (v_i − v_j) · ∇_i W_ij,
/// over soil and boundary neighbours (the ghosts' mirrored velocity keeps the walls impermeable).
#include <span>

#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// Dρ_i/Dt of soil particle i with the velocities (vx, vy).
inline double density_rate_of(const Particles& p, const NeighbourList& nl, std::size_t i,
                              std::span<const double> vx, std::span<const double> vy) {
  double rate = 0.0;
  for (std::size_t k = nl.begin(i); k < nl.end(i); ++k) {
    const auto j = static_cast<std::size_t>(nl.neighbour[k]);
    rate += p.mass[j] * ((vx[i] - vx[j]) * nl.gx[k] + (vy[i] - vy[j]) * nl.gy[k]);
  }
  return rate;
}

/// Fills p.density_rate for every soil particle from p.vx, p.vy (orphaned OpenMP loop).
inline void compute_density_rate(Particles& p, const NeighbourList& nl) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    p.density_rate[i] = density_rate_of(p, nl, i, p.vx, p.vy);
  }
}

}  // namespace soilsph::sph
