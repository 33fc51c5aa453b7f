#pragma once
/// @file
/// The stress update: each soil particle's state is advanced by the constitutive model with the
/// strain increment ε̇Δt and spin increment ω̇Δt from eq 23. The model does the Jaumann terms
/// (eq 21/28) inside its update (constitutive/rotation.h) and its chosen integrator the rest.
/// Templated on the model type so that the update is a direct call (inlined with LTO).
#include "sph/particles.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// State of every soil particle after dt, and the in-plane stress copied for the momentum stage.
template <class Model>
void update_stress(const Model& model, Particles& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    p.state[i] = model.update(p.state[i], strain_rate(p, i) * dt, spin_rate(p, i) * dt);
    const Mat3& sigma = p.state[i].stress;
    p.sxx[i] = sigma(0, 0), p.syy[i] = sigma(1, 1), p.sxy[i] = sigma(0, 1);
  }
}

}  // namespace soilsph::sph
