#pragma once
/// @file
/// The resultant force the soil exerts on each boundary: N per metre of thickness in the plane (plane
/// strain), N in space.
///
/// A wall acts on the soil only through its ghost particles, by the pair terms of eq 12 (stress,
/// artificial viscosity and artificial stress). The force on soil particle i from the ghosts of wall
/// w is m_i Σ_{j ∈ ghosts(w)} a_ij; the wall feels the opposite, so
///   F_w = − Σ_i m_i Σ_{j ∈ ghosts(w)} a_ij.
/// The soil–soil pair terms cancel in pairs (m_i a_ij = −m_j a_ji), so Σ_w F_w = M g − Σ_i m_i a_i:
/// at rest the walls carry the soil's weight. The pairs are those of the step's acceleration
/// (stages/momentum.h, PairAcceleration): call between the acceleration and the next change of σ,
/// v or the pairs.
#include <vector>

#include "sph/geometry/vec3.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/momentum.h"

namespace soilsph::sph {

/// F_w for every wall index w < walls (ghosts carry their wall's index, ParticlesOf::wall_id).
template <int dim>
std::vector<Vec<dim>> boundary_forces(const ParticlesOf<dim>& p, const PairList<dim>& nl,
                                      const MomentumParamsOf<dim>& m, std::size_t walls);

}  // namespace soilsph::sph
