#pragma once
/// @file
/// What `soilsph collapse` and `soilsph check` do alike before a run, so that a scene `check`
/// accepts is one `collapse` starts, and a refusal reads the same in both: the cost estimated and
/// checked, the particles built, the gauges placed. Each step throws ParameterError (exit 2).
#include <optional>

#include "sph/feasibility.h"
#include "sph/output/histories.h"
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/solver.h"

namespace soilsph::cli {

/// Share of this machine's memory a run may plan to use.
inline constexpr double kUsableMemoryShare = 0.8;

/// The run's cost (sph/feasibility.h), refused past the scene's limits or kUsableMemoryShare of
/// this machine's memory.
template <class SceneT>
sph::RunEstimate feasible_estimate(const SceneT& scene);

/// The soil and wall particles at rest in their geostatic state, as a collapse starts from them
/// (before any gravity-loading relaxation); a lattice or state the --set options made impossible is
/// blamed on them.
sph::Particles starting_particles(const sph::Scene& scene);

/// The histories the scene asks for ([output] history_interval > 0) with its gauges placed on
/// `particles` (refused if one lies outside the soil), before any file is touched; else nothing.
template <int dim>
std::optional<sph::HistoriesOf<dim>> scene_histories(const sph::SceneOf<dim>& scene,
                                                     const sph::ParticlesOf<dim>& particles,
                                                     const sph::SolverSetupOf<dim>& setup) {
  if (!(scene.output.history_interval > 0.0)) return std::nullopt;
  return sph::HistoriesOf<dim>(scene, particles, setup.kernel);
}

}  // namespace soilsph::cli
