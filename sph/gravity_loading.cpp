#include "sph/dynamic_relaxation.h"
#include "sph/initial_state.h"

namespace soilsph::sph {

Scene held_still(const Scene& scene) {
  Scene held = scene;
  for (Wall& w : held.geometry.layout.walls) w.motion = WallMotion{};
  return held;
}

template GravityLoadingReport relax_under_gravity<2>(const Scene&, ParticlesOf<2>&);

}  // namespace soilsph::sph
