#include "apps/soilsph/collapse_preparation.h"

#include "sph/initial_state.h"

namespace soilsph::cli {

template <class SceneT>
sph::RunEstimate feasible_estimate(const SceneT& scene) {
  const sph::RunEstimate estimate = sph::estimate_run(scene);
  sph::check_feasible(scene, estimate, kUsableMemoryShare * sph::physical_memory());
  return estimate;
}
template sph::RunEstimate feasible_estimate(const sph::Scene&);
template sph::RunEstimate feasible_estimate(const sph::Scene3&);

sph::Particles starting_particles(const sph::Scene& scene) {
  return blaming_overrides(scene.overrides, [&] {
    sph::Particles particles = sph::build_particles(scene);
    sph::set_geostatic_state(particles, scene);
    return particles;
  });
}

}  // namespace soilsph::cli
