#include "sph/stages/momentum.h"

namespace soilsph::sph {

Acceleration acceleration_of(const Particles& p, const NeighbourList& nl, const MomentumParams& m,
                            std::size_t i, bool any_tension) {
  const PairAcceleration term(p, m, i);
  const NeighbourList::Row row = nl.row(i);
  double ax = 0.0, ay = 0.0;
#pragma omp simd reduction(+ : ax, ay)
  for (std::size_t k = 0; k < row.size; ++k) {
    const auto j = static_cast<std::size_t>(row.j[k]);
    const Acceleration a = term.stress_and_viscosity(j, row.rx[k], row.ry[k], row.gx[k], row.gy[k]);
    ax += a.x;
    ay += a.y;
  }
  if (any_tension && term.artificial_stress_enabled())
    for (std::size_t k = 0; k < row.size; ++k) {
      const auto j = static_cast<std::size_t>(row.j[k]);
      if (!term.has_artificial_stress(j)) continue;
      const Acceleration a = term.artificial_stress(j, row.w[k], row.gx[k], row.gy[k]);
      ax += a.x;
      ay += a.y;
    }
  return {ax + m.gravity.x, ay + m.gravity.y};
}

}  // namespace soilsph::sph
