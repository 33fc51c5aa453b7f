#pragma once
/// @file
/// The time step: a CFL condition on the elastic P-wave speed,
///   c = √((K + 4G/3)/ρ),   Δt = C_cfl · h / c.
/// The paper quotes c = 450–600 m/s, which Table 1 (E = 1 MPa, ν = 0.3, ρ = 2000 kg/m³) does not
/// give: there c = √((K + 4G/3)/ρ) = 25.9 m/s (paper-notes). The speed consistent with the moduli is
/// used, both here and in the artificial viscosity; it is the fastest signal in the soil, and the
/// flow speeds (≲ √(2gH) ≈ 1.1 m/s) are far below it. C_cfl is [numerics] cfl (default 0.2).
#include <cmath>

#include "constitutive/elasticity.h"

namespace soilsph::sph {

/// Elastic P-wave speed (m/s) for the moduli D and density ρ.
inline double p_wave_speed(const Moduli& D, double density) {
  return std::sqrt((D.K + 4.0 / 3.0 * D.G) / density);
}

/// Δt = C_cfl h / c (s).
inline double cfl_time_step(double cfl, double smoothing_length, double sound_speed) {
  return cfl * smoothing_length / sound_speed;
}

}  // namespace soilsph::sph
