#pragma once
/// @file
/// Leapfrog time integration (the paper's §4.1 note; Liu & Liu 2003): velocities live at half
/// steps, positions, density and stress at whole steps:
///   v^{n+½} = v^{n−½} + Δt a^n                       (kick, a^n from σ^n, ρ^n, x^n)
///   ρ^{n+1} = ρ^n + Δt Dρ/Dt,  σ^{n+1} = update(σ^n, ε̇Δt, ω̇Δt)   (rates from v^{n+½} at x^n)
///   x^{n+1} = x^n + Δt v^{n+½}                        (drift)
/// The run starts at rest, v^{−½} = 0. The rates over [t^n, t^{n+1}] use the mid-step velocity, so
/// the scheme is second order for positions and centred for the stress increment.
#include "sph/particles.h"

namespace soilsph::sph {

/// v^{n+½} = v^{n−½} + Δt a^n for the soil.
inline void kick(Particles& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    p.vx[i] += dt * p.ax[i];
    p.vy[i] += dt * p.ay[i];
  }
}

/// ρ^{n+1} = ρ^n + Δt Dρ/Dt and x^{n+1} = x^n + Δt v^{n+½} for the soil; the boundary is fixed.
inline void drift(Particles& p, double dt) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    p.density[i] += dt * p.density_rate[i];
    p.x[i] += dt * p.vx[i];
    p.y[i] += dt * p.vy[i];
  }
}

}  // namespace soilsph::sph
