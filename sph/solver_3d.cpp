#include <vector>

#include "sph/initial_state_3d.h"
#include "sph/setup_parts.h"
#include "sph/solver.h"

namespace soilsph::sph {

SolverSetupOf<3> make_solver_setup(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  PlaneGuard guard;
  for (const Wall3& wall : g.walls)
    guard.add(wall.plane, g.boundary_layers * g.particle_spacing, wall.motion);
  return solver_setup<3>(
      scene,
      {.guard = guard, .walls = wall_motions(scene), .potential_datum = g.floor_level, .domain = g.domain});
}

}  // namespace soilsph::sph
