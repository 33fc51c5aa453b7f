#pragma once
/// @file
/// The soil's mechanical energy at t^n, for the energy history (energy.csv): kinetic
/// E_k = Σ ½ m |v^n|² with v^n the mean of the leapfrog's v^{n−½} and v^{n+½}, and gravitational
/// potential relative to t = 0, E_p = −Σ m g·(x − x_0), over the soil particles. Their sum falls as
/// the soil dissipates (plastic work, artificial viscosity); the walls do no work on it unless they
/// move. J per metre of thickness in the plane (m is per metre there), J in space.
#include <array>
#include <span>
#include <type_traits>

#include "sph/particles.h"

namespace soilsph::sph {

struct MechanicalEnergy {
  double kinetic = 0.0;    ///< E_k (J, or J/m in the plane)
  double potential = 0.0;  ///< E_p − E_p(t = 0) (J, or J/m)
};

template <int dim>
MechanicalEnergy mechanical_energy(const ParticlesOf<dim>& p, const std::array<std::span<const double>, dim>& v_next,
                                   std::type_identity_t<Vec<dim>> gravity) {
  MechanicalEnergy e;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    Vec<dim> next;
    next.x = v_next[0][i], next.y = v_next[1][i];
    if constexpr (dim == 3) next.z = v_next[2][i];
    const Vec<dim> v = 0.5 * (p.velocity(i) + next);
    e.kinetic += 0.5 * p.mass[i] * dot(v, v);
    e.potential -= p.mass[i] * dot(gravity, p.position(i) - p.start_position(i));
  }
  return e;
}

}  // namespace soilsph::sph
