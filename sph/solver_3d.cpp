#include <vector>

#include "sph/initial_state_3d.h"
#include "sph/setup_parts.h"
#include "sph/solver.h"

namespace soilsph::sph {

SolverSetupOf<3> make_solver_setup(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  PlaneGuard guard;
  std::vector<SymmetryPlane> symmetry;
  for (std::size_t w = 0; w < g.walls.size(); ++w) {
    const Wall3& wall = g.walls[w];
    guard.add(wall.plane, g.boundary_layers * g.particle_spacing, wall.motion);
    if (!wall.symmetry_plane) continue;
    // Normal to an axis (read_boundaries_3d.cpp refuses another), so the plane is x_axis = offset.
    const int axis = axis_along(wall.plane.inward);
    symmetry.push_back({.axis = axis,
                        .offset = component(wall.plane.origin, axis),
                        .side = component(wall.plane.inward, axis) > 0.0 ? 1.0 : -1.0,
                        .wall = static_cast<int>(w)});
  }
  return solver_setup<3>(scene, {.guard = guard,
                                 .walls = wall_motions(scene),
                                 .potential_datum = g.floor_level,
                                 .domain = g.domain,
                                 .symmetry_planes = std::move(symmetry),
                                 .boundary_layers = static_cast<double>(g.boundary_layers)});
}

}  // namespace soilsph::sph
