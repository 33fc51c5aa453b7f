#pragma once
/// @file
/// The continuity equation in SPH form (paper eq 11):
///   Dρ_i/Dt = Σ_j m_j (v_i − v_j) · ∇_i W_ij,
/// over soil and boundary neighbours (the ghosts' mirrored velocity keeps the walls impermeable).
/// It is summed in the same pass as the velocity gradient (velocity_gradient.h, kinematic_rates_of).
///
/// Density diffusion ([numerics] density_diffusion = δ, default 0: eq 11 as printed). The δ-SPH
/// term of Molteni & Colagrossi (2009, Comput. Phys. Commun. 180:861) is added to eq 11,
///   Dρ_i/Dt += δ h c Σ_j (m_j/ρ_j) ψ_ij · ∇_i W_ij,   ψ_ij = 2 (ρ_j − ρ_i)(x_j − x_i)/|x_j − x_i|²,
/// with c the initial sound speed (the viscosity's c̄) and the ghosts' and images' densities as
/// mirrored. Since (x_j − x_i)·∇_i W_ij/|x_j − x_i|² = −W'(r)/r, the sum is a discrete Laplacian:
/// for a smooth field, inside, it tends to δ h c ∇²ρ (∫ 2 (x·e)² (−W'/r) dV = 2, by parts), and on
/// the lattice it is exactly δ h c ∇²ρ times the kernel's lattice moment for a quadratic ρ
/// (tests/sph3d/test_stages_3d.cpp). Why soilsph needs it: the soil's stress is integrated from
/// eq 23, not from ρ, so nothing restores a density that eq 11 drifts; ρ only sets the particles'
/// volumes m/ρ in the sums and σ/ρ² in eq 12. Where soil shears fast over a no-slip floor (the tall
/// axisymmetric column's foot) eq 11 compacts some particles to 2 ρ0 while others thin out, with no
/// neighbour coming closer; the compacted ones, whose σ/ρ² carries less of the floor's push, sink
/// towards the floor and the wall guard has to hold them (docs/validation/three-dimensions.md). The
/// term is a flux between pairs, antisymmetric for equal volumes (ψ_ji·∇_j W_ji = −ψ_ij·∇_i W_ij):
/// among soil particles of equal volume its rates sum to zero, so it spreads what eq 11 piles up
/// without adding any. The particles' masses are fixed either way.
/// Stability: explicit, with Δt = cfl h/(c + |v|) ≤ cfl h/c, it needs δ cfl h² λ ≤ 2 for the
/// largest eigenvalue λ of the sum; for the highest lattice mode at h = 1.3Δp, h² λ = 5.8 (plane,
/// cubic spline), 6.3 (plane, Wendland), 6.0 and 6.7 (space), i.e. δ × cfl ≤ 0.30–0.35; the scene
/// reader refuses more than 0.25 (kLargestDiffusionTimesCfl).
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
    p.density_rate[i] = kinematic_rates_of(p, nl, i, velocities(p)).density_rate;
  }
}

}  // namespace soilsph::sph
