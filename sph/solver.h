#pragma once
/// @file
/// The time loop of the collapse, in one place. `advance` is one leapfrog step and reads as the
/// algorithm; `run` repeats it to the end time and hands frames to the caller. Both are templates
/// on the constitutive model: the caller chooses the model once (std::visit over the Material) and
/// the per-particle update is a direct, inlinable call.
#include <chrono>
#include <cmath>

#include "sph/kernel.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/stages/artificial_stress.h"
#include "sph/stages/boundaries.h"
#include "sph/stages/continuity.h"
#include "sph/stages/leapfrog.h"
#include "sph/stages/momentum.h"
#include "sph/stages/stress_update.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// Everything fixed for a run, derived from the scene once.
struct SolverSetup {
  CubicSpline kernel;
  double time_step;    ///< Δt (s), CFL on the P-wave speed, shortened so that the end time is a whole step
  double sound_speed;  ///< c (m/s)
  std::size_t steps;   ///< steps to the end time
  double frame_interval;
  MomentumParams momentum;
  WallGuard guard;
  bool velocity_gradient_correction = false;  ///< stages/velocity_gradient.h
};

/// Derives the kernel, the time step and the stage parameters from the scene (sph/solver.cpp).
SolverSetup make_solver_setup(const Scene& scene);

/// Reusable work space of the loop (no allocation after the first step).
struct Workspace {
  NeighbourList neighbours;
  std::size_t guard_corrections = 0;  ///< times the wall guard had to act (expected 0)
};

/// One leapfrog step from t^n to t^{n+1} (stages/leapfrog.h).
template <class Model>
void advance(const Model& model, const SolverSetup& setup, Particles& p, Workspace& work) {
  const double dt = setup.time_step;
  NeighbourList& nl = work.neighbours;
  nl.build(p.x, p.y, setup.kernel, p.soil_count);  // neighbours at x^n
  mirror_stress_onto_boundary(p, nl);              // ghost σ^n, ρ^n from the soil
  mirror_velocity_onto_boundary(p, nl);            // ghost v^{n−½} (viscosity)
  if (setup.momentum.artificial_stress.enabled)
    compute_artificial_stress(p, setup.momentum.artificial_stress.epsilon);
  compute_acceleration(p, nl, setup.momentum);                           // a^n, eq 36
  kick(p, dt);                                                           // v^{n+½}
  mirror_velocity_onto_boundary(p, nl);                                  // ghost v^{n+½}
  compute_velocity_gradient(p, nl, setup.velocity_gradient_correction);  // eq 23
  compute_density_rate(p, nl);                                           // eq 11
  update_stress(model, p, dt);  // σ^{n+1}: Jaumann + constitutive update
  drift(p, dt);                 // ρ^{n+1}, x^{n+1}
  work.guard_corrections += setup.guard.apply(p);
}

struct RunStatistics {
  std::size_t steps = 0;
  double end_time = 0.0;
  double wall_seconds = 0.0;
  std::size_t guard_corrections = 0;
};

/// Runs to the end time. Calls on_frame(particles, t) at t = 0, every frame interval and at the
/// end, and on_step(t, steps) after every step.
template <class Model, class OnFrame, class OnStep>
RunStatistics run(const Model& model, const SolverSetup& setup, Particles& p, OnFrame&& on_frame,
                  OnStep&& on_step) {
  const auto start = std::chrono::steady_clock::now();
  Workspace work;
  on_frame(p, 0.0);
  double next_frame = setup.frame_interval;
  double t = 0.0;
  for (std::size_t n = 1; n <= setup.steps; ++n) {
    advance(model, setup, p, work);
    t = static_cast<double>(n) * setup.time_step;
    const bool last = n == setup.steps;
    if (t >= next_frame - 0.5 * setup.time_step || last) {
      on_frame(p, t);
      while (next_frame <= t + 0.5 * setup.time_step) next_frame += setup.frame_interval;
    }
    on_step(t, n);
  }
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  return {setup.steps, t, elapsed.count(), work.guard_corrections};
}

}  // namespace soilsph::sph
