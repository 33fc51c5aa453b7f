#include "sph/analysis/boundary_forces.h"

namespace soilsph::sph {

std::vector<Vec2> boundary_forces(const Particles& p, const NeighbourList& nl, const MomentumParams& m,
                                  std::size_t walls) {
  std::vector<Vec2> force(walls);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const PairAcceleration term(p, m, i);
    nl.for_each_pair(i, [&](const NeighbourList::Pair& q) {
      if (p.is_soil(q.j)) return;
      const auto w = static_cast<std::size_t>(p.wall_id[q.j - p.soil_count]);
      const Acceleration a = term(q);
      force[w].x -= p.mass[i] * a.x;
      force[w].y -= p.mass[i] * a.y;
    });
  }
  return force;
}

}  // namespace soilsph::sph
