#pragma once
/// @file
/// One collapse of a scene, from the scene to the deposit: the particles and their geostatic state,
/// the solver setup, the time loop with the model chosen once (std::visit), and the deposit
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
      : scene_(scene), particles_(geostatic_particles(scene)), setup_(make_solver_setup(scene)) {
    if (scene.initial.stress == InitialStress::GravityLoading) gravity_loading_ = relax_under_gravity(scene, particles_);
  }
  /// A collapse that continues from `particles` (a checkpoint's) rather than the initial column.
  Collapse(const Scene& scene, Particles particles)
      : scene_(scene), particles_(std::move(particles)), setup_(make_solver_setup(scene)) {
    copy_wall_attributes(particles_, build_particles(scene));
  }

  /// Runs the scene (solver.h, run) and returns its statistics.
  template <class OnFrame, class OnStep>
  RunStatistics run(ThreadTuner tuner, OnFrame&& on_frame, OnStep&& on_step, const RunControl& control = {}) {
    return std::visit(
        [&](const auto& model) {
          return sph::run(model, setup_, particles_, std::forward<OnFrame>(on_frame),
                          std::forward<OnStep>(on_step), tuner, control);
        },
        scene_.material);
  }
  /// Runs without frames or progress.
  RunStatistics run(ThreadTuner tuner) {
    return run(
        tuner, [](const Particles&, double) {}, [](double, std::size_t) {});
  }

  /// Runout, height and repose angle of the soil now, and the runout where the deposit is a tenth
  /// of the column's initial height thick (analysis/deposit.h).
  DepositMetrics deposit() const {
    return measure_deposit({particles_.x.data(), particles_.soil_count},
                           {particles_.y.data(), particles_.soil_count}, scene_.geometry.column_width,
                           scene_.geometry.particle_spacing, 0.1 * scene_.geometry.column_height);
  }

  const Particles& particles() const { return particles_; }
  /// The relaxation's outcome, if this collapse ran one (not when continuing from a checkpoint).
  const std::optional<GravityLoadingReport>& gravity_loading() const { return gravity_loading_; }
  const SolverSetup& setup() const { return setup_; }

 private:
  static Particles geostatic_particles(const Scene& scene) {
    Particles p = build_particles(scene);
    set_geostatic_state(p, scene);
    return p;
  }

  const Scene& scene_;
  Particles particles_;
  SolverSetup setup_;
  std::optional<GravityLoadingReport> gravity_loading_;
};

}  // namespace soilsph::sph
