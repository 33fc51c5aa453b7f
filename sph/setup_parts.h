#pragma once
/// @file
/// What the solver setups of the plane and of space (sph/solver.cpp, sph/solver_3d.cpp) derive
/// alike from a scene: the initial sound speeds of its materials and the momentum equation's
/// parameters.
#include <algorithm>
#include <vector>

#include "constitutive/material.h"
#include "sph/kernel.h"
#include "sph/scene_settings.h"
#include "sph/stages/momentum.h"
#include "sph/time_step.h"

namespace soilsph::sph {

/// The P-wave speeds of the soil at the start: the largest over the materials, and apart the
/// largest of those whose stiffness does not follow the pressure.
struct InitialSoundSpeeds {
  double largest = 0.0, constant_stiffness = 0.0;
  bool pressure_dependent = false;  ///< some material's stiffness follows the pressure
};
/// The stiffest elastic state of the soil: moduli at the largest initial pressure p0 (constant
/// elasticity ignores it; pressure-dependent MCC is stiffest at the base).
inline InitialSoundSpeeds initial_sound_speeds(const std::vector<Material>& materials, double p0) {
  InitialSoundSpeeds c;
  for (const Material& material : materials) {
    const double ck = p_wave_speed(material, p0);
    c.largest = std::max(c.largest, ck);
    if (stiffness_follows_state(material))
      c.pressure_dependent = true;
    else
      c.constant_stiffness = std::max(c.constant_stiffness, ck);
  }
  return c;
}

/// The momentum equation's parameters of a scene (stages/momentum.h).
template <int dim>
MomentumParamsOf<dim> momentum_params(const Numerics& numerics, const CubicSplineKernel<dim>& kernel,
                                      Vec<dim> gravity, double spacing, double sound_speed) {
  MomentumParamsOf<dim> momentum;
  momentum.viscosity_alpha = numerics.viscosity_alpha;
  momentum.viscosity_beta = numerics.viscosity_beta;
  momentum.sound_speed = sound_speed;
  momentum.smoothing_length = kernel.smoothing_length();
  momentum.gravity = gravity;
  if (numerics.artificial_stress)
    momentum.artificial_stress = {numerics.artificial_stress_epsilon, numerics.artificial_stress_exponent, kernel,
                                  spacing};
  return momentum;
}

}  // namespace soilsph::sph
