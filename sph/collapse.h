#pragma once
/// @file
/// One collapse of a scene, from the scene to the deposit: the particles and their geostatic state,
/// the solver setup, the time loop with each material's model chosen once per step, and the deposit
/// measures. `soilsph collapse` and `soilsph bench collapse` both run scenes through it.
#include <optional>
#include <utility>

#include "sph/analysis/deposit.h"
#include "sph/gravity_loading.h"
#include "sph/initial_state.h"
#include "sph/solver.h"

namespace soilsph::sph {

class Collapse {
 public:
  /// With [initial] stress = "gravity-loading" the soil is relaxed first (gravity_loading.h).
  explicit Collapse(const Scene& scene)
      : scene_(scene),
        particles_(geostatic_particles(scene)),
        setup_(make_solver_setup(scene)),
        groups_(material_groups(scene.materials, particles_)) {
    if (scene.initial.stress == InitialStress::GravityLoading) gravity_loading_ = relax_under_gravity(scene, particles_);
  }
  /// A collapse that continues from `particles` (a checkpoint's) rather than the initial column.
  Collapse(const Scene& scene, Particles particles)
      : scene_(scene), particles_(std::move(particles)), setup_(make_solver_setup(scene)) {
    const Particles built = build_particles(scene);
    copy_wall_attributes(particles_, built);
    particles_.material = built.material;  // the order of the soil is the scene's, as built
    groups_ = material_groups(scene.materials, particles_);
  }

  /// Runs the scene (solver.h, run) and returns its statistics.
  template <class OnFrame, class OnStep>
  RunStatistics run(ThreadTuner tuner, OnFrame&& on_frame, OnStep&& on_step, const RunControl& control = {}) {
    return run_groups(groups_, setup_, particles_, std::forward<OnFrame>(on_frame), std::forward<OnStep>(on_step),
                      tuner, control);
  }
  /// Runs without frames or progress.
  RunStatistics run(ThreadTuner tuner) {
    return run(
        tuner, [](const Particles&, double) {}, [](double, std::size_t) {});
  }

  /// Runout, height and repose angle of the soil now, and the runout where the deposit is
  /// [deposit] toe_thickness thick, in the scene's [deposit] frame (analysis/deposit.h).
  DepositMetrics deposit() const {
    return measure_deposit({particles_.x.data(), particles_.soil_count}, {particles_.y.data(), particles_.soil_count},
                           scene_.deposit, scene_.geometry.particle_spacing);
  }

  const Particles& particles() const { return particles_; }
  /// The relaxation's outcome, if this collapse ran one (not when continuing from a checkpoint).
  const std::optional<GravityLoadingReport>& gravity_loading() const { return gravity_loading_; }
  const SolverSetup& setup() const { return setup_; }

 private:
  const Scene& scene_;
  Particles particles_;
  SolverSetup setup_;
  MaterialGroups groups_;  ///< the soil's materials, each a range of particles
  std::optional<GravityLoadingReport> gravity_loading_;
};

}  // namespace soilsph::sph
