#include "sph/dynamic_relaxation.h"
#include "sph/initial_state_3d.h"
#include "sph/read_boundaries_3d.h"

namespace soilsph::sph {

Scene3 held_still(const Scene3& scene) {
  Scene3 held = scene;
  Geometry3& g = held.geometry;
  g.walls.insert(g.walls.end(), g.withdrawn_walls.begin(), g.withdrawn_walls.end());
  for (Wall3& w : g.walls) w.motion = WallMotionOf<3>{};
  // The withdrawn walls' ghosts inside the domain, as the scene's own walls' (scene_3d.cpp).
  g.domain = domain_around_walls(g.domain, g.withdrawn_walls,
                                 g.boundary_layers * g.particle_spacing + 2.0 * g.smoothing_length());
  return held;
}

template GravityLoadingReport relax_under_gravity<3>(const Scene3&, ParticlesOf<3>&);

}  // namespace soilsph::sph
