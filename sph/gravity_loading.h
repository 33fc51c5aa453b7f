#pragma once
/// @file
/// The gravity-loading stage (`[initial] stress = "gravity-loading"`): before
/// t = 0 the soil, starting from K0 under its local free surface, is relaxed quasi-statically under
/// gravity with every wall in place and still, by dynamic relaxation (Underwood 1983, "Dynamic
/// relaxation", in Belytschko & Hughes (eds.), Computational Methods for Transient Analysis, ch. 5:
/// the explicit dynamics of the structure with artificial damping, run until it is at rest, is the
/// static solution). The damping here is the simplest of its kinds, mass-proportional: every step
/// the soil's velocities are scaled by (1 − damping), as SPH geomechanics does to settle a geostatic
/// state (Bui et al. 2008, Int. J. Numer. Anal. Meth. Geomech. 32, 1537–1570, who damp the momentum
/// equation until the initial stress is in equilibrium). It stops once both
///   kinetic energy / (M |g| H) < kinetic tolerance       (M the soil's mass, H its height)
///   max |Δσ_ij| over one step / (ρ |g| H) < stress tolerance
/// hold; then the velocities are zeroed and the run starts at t = 0 from the relaxed positions,
/// densities and stresses, the walls as the scene has them at t = 0 (a wall withdrawn at t = 0 held
/// the soil during the relaxation, as the column's did before it was withdrawn). The hardening state
/// starts from the relaxed stress with the scene's OCR (the model's initial_preconsolidation: for
/// MCC p_c = max(OCR p_c,yield, floor), so a relaxed stress on the yield surface stays on it at
/// OCR = 1), and the plastic strain of the relaxation is not counted.
/// One implementation for the plane and for space: in space M is the soil's mass (kg), in the plane
/// its mass per metre of thickness, and Δσ_ij runs over the six components (the plane's three).
#include <cstddef>

#include "sph/particles.h"
#include "sph/scene_3d.h"

namespace soilsph::sph {

/// What the relaxation reached (summary.json "initial_stress").
struct GravityLoadingReport {
  std::size_t steps = 0;        ///< relaxation steps taken
  double time = 0.0;            ///< relaxation time simulated (s), not part of the run's time
  double kinetic_energy = 0.0;  ///< kinetic energy / (M |g| H) at the last step
  double stress_change = 0.0;   ///< max |Δσ_ij| over the last step / (ρ |g| H)
};

/// Relaxes the soil of `particles` (the scene's geostatic_particles, initial_state.h and
/// initial_state_3d.h) as above and leaves it at rest in the relaxed state. Throws
/// std::runtime_error, naming the tolerances reached, if the relaxation has not settled by
/// [initial] gravity_loading_max_time. Instantiated for dim = 2 (Scene) and 3 (Scene3).
template <int dim>
GravityLoadingReport relax_under_gravity(const SceneOf<dim>& scene, ParticlesOf<dim>& particles);

}  // namespace soilsph::sph
