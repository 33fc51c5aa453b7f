#pragma once
/// @file
/// One collapse of a scene of space (sph/scene_3d.h), from the scene to the deposit: the particles
/// and their geostatic state (initial_state_3d.h), relaxed under gravity first if the scene asks
/// (gravity_loading.h), the solver setup (solver_3d.cpp), the time loop
/// of sph/solver.h instantiated for three dimensions, and the deposit measures of its shape: the
/// axisymmetric column's (analysis/axisymmetric_deposit.h) or the slab's, the 2D column's measures
/// of the particles seen along z.
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "sph/analysis/axisymmetric_deposit.h"
#include "sph/analysis/deposit.h"
#include "sph/gravity_loading.h"
#include "sph/initial_state.h"
#include "sph/initial_state_3d.h"
#include "sph/solver.h"

namespace soilsph::sph {

class Collapse3 {
 public:
  /// With [initial] stress = "gravity-loading" the soil is relaxed first (gravity_loading.h).
  explicit Collapse3(const Scene3& scene)
      : scene_(scene),
        particles_(geostatic_particles(scene)),
        setup_(make_solver_setup(scene)),
        groups_(material_groups(scene.materials, particles_)) {
    if (scene.initial.stress == InitialStress::GravityLoading)
      gravity_loading_ = relax_under_gravity(scene, particles_);
  }
  /// A collapse that continues from `particles` (a checkpoint's) rather than the initial column: the
  /// ghosts' wall attributes, which a checkpoint does not hold, and the soil's materials come from the
  /// scene's particles as built.
  Collapse3(const Scene3& scene, ParticlesOf<3> particles)
      : scene_(scene), particles_(std::move(particles)), setup_(make_solver_setup(scene)) {
    const ParticlesOf<3> built = build_particles_3d(scene);
    copy_wall_attributes(particles_, built);
    particles_.material = built.material;
    groups_ = material_groups(scene.materials, particles_);
  }

  /// Runs the scene (solver.h, run_groups) and returns its statistics.
  template <class OnFrame, class OnStep>
  RunStatistics run(ThreadTuner tuner, OnFrame&& on_frame, OnStep&& on_step, const RunControlOf<3>& control = {}) {
    return run_groups(groups_, setup_, particles_, std::forward<OnFrame>(on_frame), std::forward<OnStep>(on_step),
                      tuner, control);
  }
  RunStatistics run(ThreadTuner tuner) {
    return run(
        tuner, [](const ParticlesOf<3>&, double) {}, [](double, std::size_t) {});
  }

  /// The axisymmetric column's deposit now: runout radius from the axis (mean and spread over
  /// sectors of about 10°, and where the deposit is a tenth of the soil's initial height thick, as
  /// the 2D column's runout_thick_m) and height on the axis.
  AxisymmetricDeposit axisymmetric_deposit() const {
    const Geometry3& g = scene_.geometry;
    return measure_axisymmetric_deposit(soil_positions(), g.deposit_axis, g.particle_spacing,
                                        g.azimuth_span_deg, default_sectors(g.azimuth_span_deg),
                                        0.1 * (g.surface_level - g.floor_level));
  }
  /// The slab's deposit: the 2D column's measures (runout, height, repose angle, runout where the
  /// deposit is H0/10 thick) of the body linked in space, seen along z, the fixed wall at x = W.
  DepositMetrics slab_deposit() const {
    const Geometry3& g = scene_.geometry;
    const std::size_t n = particles_.soil_count;
    return measure_slab_deposit({particles_.x.data(), n}, {particles_.y.data(), n}, {particles_.z.data(), n},
                                g.column_width, g.particle_spacing, 0.1 * g.column_height);
  }

  const ParticlesOf<3>& particles() const { return particles_; }
  /// The relaxation's outcome, if this collapse ran one (not when continuing from a checkpoint).
  const std::optional<GravityLoadingReport>& gravity_loading() const { return gravity_loading_; }
  const SolverSetupOf<3>& setup() const { return setup_; }

 private:
  std::vector<Vec3> soil_positions() const {
    std::vector<Vec3> x(particles_.soil_count);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = particles_.position(i);
    return x;
  }

  const Scene3& scene_;
  ParticlesOf<3> particles_;
  SolverSetupOf<3> setup_;
  MaterialGroups groups_;
  std::optional<GravityLoadingReport> gravity_loading_;
};

}  // namespace soilsph::sph
