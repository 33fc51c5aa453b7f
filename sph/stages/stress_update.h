#pragma once
/// @file
/// The stress update: each soil particle's state is advanced by the constitutive model with the
/// strain increment ε̇Δt and spin increment ω̇Δt from eq 23. The model does the Jaumann terms
/// (eq 21/28) inside its update (constitutive/rotation.h) and its chosen integrator the rest.
/// Templated on the model type so that the update is a direct call (inlined with LTO).
#include <optional>
#include <stdexcept>
#include <string>

#include "constitutive/integrators/integrator.h"
#include "sph/particles.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// State of every soil particle after dt, and the in-plane stress copied for the momentum stage.
/// A scheme that cannot complete an update throws; an exception must not leave an OpenMP loop (that
/// terminates the program), so the first failure is kept and rethrown after the loop as an
/// IntegrationError naming the particle.
template <class Model>
void update_stress(const Model& model, Particles& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
  std::optional<std::string> failure;
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    try {
      p.state[i] = model.update(p.state[i], strain_rate(p, i) * dt, spin_rate(p, i) * dt);
    } catch (const std::exception& e) {
#pragma omp critical(soilsph_stress_failure)
      if (!failure) failure = "stress update of soil particle " + std::to_string(i) + ": " + e.what();
      continue;
    }
    const Mat3& sigma = p.state[i].stress;
    p.sxx[i] = sigma(0, 0), p.syy[i] = sigma(1, 1), p.sxy[i] = sigma(0, 1);
  }
  if (failure) throw IntegrationError(*failure);
}

}  // namespace soilsph::sph
