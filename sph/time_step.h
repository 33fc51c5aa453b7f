#pragma once
/// @file
/// The time step: an acoustic CFL condition on the elastic P-wave speed and the flow speed,
///   c = √((K + 4G/3)/ρ),   Δt = C_cfl · h / (c + |v|_max),
/// re-evaluated every step from the current state (as SPHinXsys's acoustic time step, which takes
/// the bulk speed √(K/ρ) instead: the P-wave speed is the fastest signal in an elastic solid, 1.27×
/// the bulk speed at ν = 0.3). c is the largest over the soil: constant for constant elasticity,
/// recomputed from the current pressures at each neighbour search for pressure-dependent MCC.
/// The paper quotes c = 450–600 m/s, which Table 1 (E = 1 MPa, ν = 0.3, ρ = 2000 kg/m³) does not
/// give: there c = 25.9 m/s (paper-notes). C_cfl is [numerics] cfl; its default comes from a
/// measured stability sweep (docs/validation/time-step.md).
#include <algorithm>
#include <cmath>

#include "constitutive/elasticity.h"
#include "constitutive/material.h"
#include "constitutive/state.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// Elastic P-wave speed (m/s) for the moduli D and density ρ.
inline double p_wave_speed(const Moduli& D, double density) {
  return std::sqrt((D.K + 4.0 / 3.0 * D.G) / density);
}

/// The P-wave speed (m/s) of a material at mean pressure p, with its own density.
inline double p_wave_speed(const Material& material, double p) {
  const Elasticity elasticity = std::visit([](const auto& m) { return m.elasticity(); }, material);
  return p_wave_speed(elasticity.at(p), density(material));
}

/// Whether a material's stiffness follows its state, so that c is re-evaluated from the particles:
/// pressure-dependent elasticity (MCC's κ), or a UMAT plug-in (its DDSDDE at each particle's state,
/// UmatModel::wave_modulus).
template <class Model>
bool stiffness_follows_state(const Model& model) {
  if constexpr (requires { model.wave_modulus(State{}, UmatCall{}); })
    return true;
  else
    return model.elasticity().kind() == Elasticity::Kind::PressureDependent;
}
inline bool stiffness_follows_state(const Material& material) {
  return std::visit([](const auto& m) { return stiffness_follows_state(m); }, material);
}

/// Δt = C_cfl h / (c + v_max) (s).
inline double cfl_time_step(double cfl, double smoothing_length, double sound_speed, double max_speed = 0.0) {
  return cfl * smoothing_length / (sound_speed + max_speed);
}

/// The largest P-wave speed of the soil particles [begin, end) at their current pressure and density.
template <int dim>
double largest_p_wave_speed(const Elasticity& elasticity, const ParticlesOf<dim>& p, std::size_t begin, std::size_t end) {
  double c = 0.0;
  for (std::size_t i = begin; i < end; ++i)
    c = std::max(c, p_wave_speed(elasticity.at(mean_pressure(p.state[i].stress)), p.density[i]));
  return c;
}

}  // namespace soilsph::sph
