#include "sph/analysis/boundary_forces.h"

namespace soilsph::sph {

template <int dim>
std::vector<Vec<dim>> boundary_forces(const ParticlesOf<dim>& p, const PairList<dim>& nl,
                                      const MomentumParamsOf<dim>& m, std::size_t walls) {
  std::vector<Vec<dim>> force(walls);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const PairAccelerationOf<dim> term(p, m, i);
    for_each_pair_vectors(p, nl, i, [&](const PairVectors<dim>& q) {
      if (p.is_soil(q.j)) return;
      const auto w = static_cast<std::size_t>(p.wall_id[q.j - p.soil_count]);
      const AccelerationOf<dim> a = term(q);
      force[w].x -= p.mass[i] * a[0];
      force[w].y -= p.mass[i] * a[1];
      if constexpr (dim == 3) force[w].z -= p.mass[i] * a[2];
    });
  }
  return force;
}

template std::vector<Vec2> boundary_forces(const ParticlesOf<2>&, const PairList<2>&, const MomentumParamsOf<2>&,
                                           std::size_t);
template std::vector<Vec3> boundary_forces(const ParticlesOf<3>&, const PairList<3>&, const MomentumParamsOf<3>&,
                                           std::size_t);

}  // namespace soilsph::sph
