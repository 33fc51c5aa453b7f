#pragma once
/// @file
/// The stress update: each soil particle's state is advanced by the constitutive model with the
/// strain increment ε̇Δt and spin increment ω̇Δt from eq 23. The model does the Jaumann terms
/// (eq 21/28) inside its update (constitutive/rotation.h) and its chosen integrator the rest.
/// Templated on the model type so that the update is a direct call (inlined with LTO).
///
/// A scheme that cannot complete an update throws; an exception must not leave an OpenMP region
/// (that terminates the program), so a failure is kept in a StepFailure, the first one wins, and
/// the caller reports it after the loop as an IntegrationError naming the particle.
#include <optional>
#include <stdexcept>
#include <string>

#include "constitutive/integrators/integrator.h"
#include "sph/particles.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// The first failure of a parallel loop, shared by its threads.
class StepFailure {
 public:
  void record(const std::string& message) {
#pragma omp critical(soilsph_step_failure)
    if (!message_) message_ = message;
  }
  bool failed() const { return message_.has_value(); }
  const std::string& message() const { return *message_; }
  void clear() { message_.reset(); }

 private:
  std::optional<std::string> message_;
};

/// σ^{n+1} of soil particle i for the velocity gradient L over dt, and its in-plane stress copied
/// for the momentum stage; a failed update is recorded and leaves the particle unchanged.
template <class Model>
void update_particle_stress(const Model& model, Particles& p, std::size_t i, const VelocityGradient& L,
                            double dt, StepFailure& failure) {
  try {
    p.state[i] = model.update(p.state[i], L.strain_rate() * dt, L.spin_rate() * dt);
  } catch (const std::exception& e) {
    failure.record("stress update of soil particle " + std::to_string(i) + ": " + e.what());
    return;
  }
  const Mat3& sigma = p.state[i].stress;
  p.sxx[i] = sigma(0, 0), p.syy[i] = sigma(1, 1), p.sxy[i] = sigma(0, 1);
}

/// Every soil particle's state after dt from the stored velocity gradient (p.lxx …); throws
/// IntegrationError for the first failed update. Not for use inside a parallel region.
template <class Model>
void update_stress(const Model& model, Particles& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
  StepFailure failure;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    update_particle_stress(model, p, i, stored_velocity_gradient(p, i), dt, failure);
  }
  if (failure.failed()) throw IntegrationError(failure.message());
}

}  // namespace soilsph::sph
