#include "sph/analysis/boundary_forces.h"

namespace soilsph::sph {

std::vector<Vec2> boundary_forces(const Particles& p, const NeighbourList& nl, const MomentumParams& m,
                                  std::size_t walls) {
  std::vector<Vec2> force(walls);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const PairAcceleration term(p, m, i);
    for_each_pair_vectors(p, nl, i, [&](const PairVectors<2>& q) {
      if (p.is_soil(q.j)) return;
      const auto w = static_cast<std::size_t>(p.wall_id[q.j - p.soil_count]);
      const AccelerationOf<2> a = term(q);
      force[w].x -= p.mass[i] * a[0];
      force[w].y -= p.mass[i] * a[1];
    });
  }
  return force;
}

}  // namespace soilsph::sph
