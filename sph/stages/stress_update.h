#pragma once
/// @file
/// The stress update: each soil particle's state is advanced by the constitutive model with the
/// strain increment ε̇Δt and spin increment ω̇Δt from eq 23. The model does the Jaumann terms
/// (eq 21/28) inside its update (constitutive/rotation.h) and its chosen integrator the rest.
/// Templated on the model type so that the update is a direct call (inlined with LTO).
///
/// A scheme that cannot complete an update throws; an exception must not leave an OpenMP region
/// (that terminates the program), so a failure is kept in a StepFailure, the first one wins, and
/// the caller reports it after the loop as an IntegrationError naming the particle. Before that, a
/// failed update is split and then handed to a fallback scheme (update_splitting_on_failure).
#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>

#include "constitutive/integrators/integrator.h"
#include "constitutive/models/umat.h"
#include "constitutive/viscoplastic_relaxation.h"
#include "sph/particles.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// The stress updates of one step, shared by the threads of a parallel loop: the first failure
/// (the first one wins) and how many updates needed a fallback.
class StepFailure {
 public:
  void record(const std::string& message) {
#pragma omp critical(soilsph_step_failure)
    if (!message_) message_ = message;
  }
  bool failed() const {
    return message_.has_value();
  }
  const std::string& message() const {
    return *message_;
  }
  void note_fallback() {
    fallback_updates_.fetch_add(1, std::memory_order_relaxed);
  }
  std::size_t fallback_updates() const {
    return fallback_updates_.load(std::memory_order_relaxed);
  }
  /// Continues the count of a run that is resumed.
  void restore_fallback_updates(std::size_t count) {
    fallback_updates_.store(count, std::memory_order_relaxed);
  }

 private:
  std::optional<std::string> message_;
  std::atomic<std::size_t> fallback_updates_{0};
};

/// Most halvings of a step's increment whose update fails (up to 2^4 parts), as the material-point
/// driver does (verification/driver/mixed_control.h).
inline constexpr int kMaxStressSplits = 4;

/// The model a failed update falls back on: the same parameters with `substep` (error-controlled
/// substepping, which does not rely on a Newton iteration) for a model with a choice of scheme;
/// the model itself otherwise. Built once per run.
template <class Model>
Model fallback_model(const Model& model) {
  if constexpr (requires { model.params().integrator; }) {
    auto params = model.params();
    params.integrator = Integrator::Substep;
    return Model(params);
  } else {
    return model;
  }
}

/// Stress and p_c below this (Pa) are none at all for a soil (ρ g Δp is ~2 Pa at 0.1 mm).
inline constexpr double kNegligibleStress = 1e-3;

/// The model's update for the increments (dε, dω). One that throws IntegrationError (an implicit
/// return that does not converge for a coarse or degenerate increment) is redone as 2, 4, …
/// 2^kMaxStressSplits equal parts, as the material-point driver does, and then once by the fallback
/// model; the rotation of the parts composes to the whole one to second order. If that fails too and
/// the particle carries no stress and no p_c to speak of (a free-surface MCC particle whose yield
/// surface has shrunk to p_c ~ 1e-11 Pa: measured at 0.5 mm), it is left stress-free, the apex of its
/// vanished surface, as SPH soil codes treat a particle that has lost all strength. Otherwise the
/// error is passed on. Every such update is counted.
template <class Model>
State update_splitting_on_failure(const Model& model, const Model& fallback, const State& state,
                                  const Mat3& strain, const Mat3& spin, StepFailure& log) {
  try {
    return model.update(state, strain, spin);
  } catch (const IntegrationError&) {
  }
  log.note_fallback();
  for (int halvings = 1; halvings <= kMaxStressSplits; ++halvings) {
    const int parts = 1 << halvings;
    try {
      State s = state;
      for (int k = 0; k < parts; ++k) s = model.update(s, strain / parts, spin / parts);
      return s;
    } catch (const IntegrationError&) {
    }
  }
  try {
    return fallback.update(state, strain, spin);
  } catch (const IntegrationError&) {
    if (state.stress.norm() > kNegligibleStress || state.pc > kNegligibleStress) throw;
  }
  State stress_free = state;
  stress_free.stress.setZero();
  return stress_free;
}

/// The z coordinate of particle i: 0 in the plane.
template <int dim>
double z_coordinate(const ParticlesOf<dim>& p, std::size_t i) {
  if constexpr (dim == 2)
    return 0.0;
  else
    return p.z[i];
}

/// Where and when a UMAT plug-in is called for soil particle i over dt: NOEL the particle's id + 1,
/// DTIME the step, CELENT the particle's spacing: √(m/ρ) in the plane (m per metre of thickness),
/// ∛(m/ρ) in space; COORDS its position.
template <int dim>
UmatCall umat_call_at(const ParticlesOf<dim>& p, std::size_t i, double dt) {
  const double volume = p.mass[i] / p.density[i];
  return {.element = static_cast<int>(p.id[i]) + 1,
          .time_increment = dt,
          .characteristic_length = dim == 2 ? std::sqrt(volume) : std::cbrt(volume),
          .coordinates = soilsph::Vec3(p.x[i], p.y[i], z_coordinate(p, i))};
}

/// σ^{n+1} of soil particle i for the velocity gradient L over dt, and the stress the momentum stage
/// reads (in-plane in the plane, all six components in space) copied from it; a failed update is
/// recorded and leaves the particle unchanged. A material with a viscoplastic relaxation time relaxes
/// towards the model's update (viscoplastic_relaxation.h).
template <class Model, int dim>
void update_particle_stress(const Model& model, const Model& fallback, ParticlesOf<dim>& p, std::size_t i,
                            const VelocityGradientOf<dim>& L, double dt, StepFailure& failure) {
  try {
    const Mat3 strain = L.strain_increment(dt), spin = L.spin_increment(dt);
    State next;
    if constexpr (requires { model.update(p.state[i], strain, spin, UmatCall{}); }) {
      next = model.update(p.state[i], strain, spin, umat_call_at(p, i, dt));  // a UMAT learns where and when
    } else {
      next = update_splitting_on_failure(model, fallback, p.state[i], strain, spin, failure);
    }
    if constexpr (requires { model.params().viscoplastic_relaxation_time; }) {
      if (const double tau = model.params().viscoplastic_relaxation_time; tau > 0.0)
        next = relax_viscoplastically(model.elasticity(), p.state[i], strain, spin, next, dt / tau);
    }
    p.state[i] = next;
  } catch (const std::exception& e) {
    failure.record("stress update of soil particle " + std::to_string(p.id[i]) + ": " + e.what());
    return;
  }
  const Mat3& sigma = p.state[i].stress;
  p.sxx[i] = sigma(0, 0), p.syy[i] = sigma(1, 1), p.sxy[i] = sigma(0, 1);
  if constexpr (dim == 3) p.szz[i] = sigma(2, 2), p.sxz[i] = sigma(0, 2), p.syz[i] = sigma(1, 2);
}

/// Every soil particle's state after dt from the stored velocity gradient (p.lxx …); throws
/// IntegrationError for the first failed update. Not for use inside a parallel region.
template <class Model, int dim>
void update_stress(const Model& model, ParticlesOf<dim>& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
  StepFailure failure;
  const Model fallback = fallback_model(model);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    update_particle_stress(model, fallback, p, i, stored_velocity_gradient(p, i), dt, failure);
  }
  if (failure.failed()) throw IntegrationError(failure.message());
}

}  // namespace soilsph::sph
