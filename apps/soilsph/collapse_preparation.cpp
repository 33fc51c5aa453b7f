#include "apps/soilsph/collapse_preparation.h"

#include "sph/initial_state.h"

namespace soilsph::cli {

sph::RunEstimate feasible_estimate(const sph::Scene& scene) {
  const sph::RunEstimate estimate = sph::estimate_run(scene);
  sph::check_feasible(scene, estimate, kUsableMemoryShare * sph::physical_memory());
  return estimate;
}

sph::Particles starting_particles(const sph::Scene& scene) {
  return blaming_overrides(scene.overrides, [&] {
    sph::Particles particles = sph::build_particles(scene);
    sph::set_geostatic_state(particles, scene);
    return particles;
  });
}

std::optional<sph::Histories> scene_histories(const sph::Scene& scene, const sph::Particles& particles,
                                              const sph::SolverSetup& setup) {
  if (!(scene.output.history_interval > 0.0)) return std::nullopt;
  return sph::Histories(scene, particles, setup.kernel);
}

}  // namespace soilsph::cli
