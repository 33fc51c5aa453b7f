#pragma once
/// @file
/// Whole-soil measures for the summary and the tests.
#include <algorithm>
#include <cmath>

#include "sph/particles.h"

namespace soilsph::sph {

/// Largest soil particle speed (m/s).
inline double max_speed(const Particles& p) {
  double v2 = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) v2 = std::max(v2, p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i]);
  return std::sqrt(v2);
}

/// Kinetic energy of the soil, Σ ½ m v²: per metre of thickness in the plane (J/m), J in space.
template <int dim>
double kinetic_energy(const ParticlesOf<dim>& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    double v2 = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
    if constexpr (dim == 3) v2 += p.vz[i] * p.vz[i];
    e += 0.5 * p.mass[i] * v2;
  }
  return e;
}

/// Highest soil particle (m).
inline double top_of_soil(const Particles& p) {
  return *std::max_element(p.y.begin(), p.y.begin() + static_cast<std::ptrdiff_t>(p.soil_count));
}

/// True if every soil position, velocity, density and stress is finite.
inline bool all_finite(const Particles& p) {
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    if (!std::isfinite(p.x[i] + p.y[i] + p.vx[i] + p.vy[i] + p.density[i]) || !p.state[i].stress.allFinite())
      return false;
  }
  return true;
}

}  // namespace soilsph::sph
