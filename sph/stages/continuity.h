#pragma once
/// @file
/// The continuity equation in SPH form (paper eq 11):
///   Dρ_i/Dt = Σ_j m_j (v_i − v_j) · ∇_i W_ij,
/// over soil and boundary neighbours (the ghosts' mirrored velocity keeps the walls impermeable).
/// It is summed in the same pass as the velocity gradient (velocity_gradient.h, kinematic_rates_of).
#include <span>

#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// Fills p.density_rate for every soil particle from its velocities (orphaned OpenMP loop).
template <int dim>
void compute_density_rate(ParticlesOf<dim>& p, const PairList<dim>& nl) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    p.density_rate[i] = kinematic_rates_of(p, nl, i, velocities(p), false).density_rate;
  }
}

}  // namespace soilsph::sph
