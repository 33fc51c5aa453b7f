#pragma once
/// @file
/// What the solver setups of the plane and of space (sph/solver.cpp, sph/solver_3d.cpp) derive
/// alike from a scene: the initial sound speeds of its materials, the momentum equation's
/// parameters, and the setup itself from what each dimension's geometry adds (GeometryParts).
#include <algorithm>
#include <cmath>
#include <vector>

#include "constitutive/material.h"
#include "sph/kernel.h"
#include "sph/scene_settings.h"
#include "sph/solver.h"
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
MomentumParamsOf<dim> momentum_params(const Numerics& numerics, const SmoothingKernel<dim>& kernel,
                                      Vec<dim> gravity, double spacing, double sound_speed) {
  MomentumParamsOf<dim> momentum;
  momentum.viscosity_alpha = numerics.viscosity_alpha;
  momentum.viscosity_beta = numerics.viscosity_beta;
  momentum.sound_speed = sound_speed;
  momentum.smoothing_length = kernel.smoothing_length();
  momentum.gravity = gravity;
  if (numerics.artificial_stress)
    momentum.artificial_stress = {numerics.artificial_stress_epsilon, numerics.artificial_stress_exponent,
                                  kernel, spacing};
  return momentum;
}

/// How far from a symmetry plane the soil has mirror images (stages/mirror_images.h): the search
/// radius 2h + s, the images every soil row needs, plus the diagonal of the ghost layers' corner
/// block (√3 × their depth), so that a ghost behind the plane, which takes the images into its
/// kernel average as the soil they stand for, has every one within its search radius too.
template <int dim>
double image_reach(const SmoothingKernel<dim>& kernel, double ghost_depth) {
  return (2.0 + PairList<dim>::kSkinRatio) * kernel.smoothing_length() + std::sqrt(3.0) * ghost_depth;
}

/// What a scene's geometry gives a solver setup, which each dimension derives its own way.
template <int dim>
struct GeometryParts {
  WallGuardOf<dim> guard;
  WallMotionsOf<dim> walls;
  double potential_datum;  ///< height of the lowest wall along −g (m)
  DomainOf<dim> domain;
  std::vector<SymmetryPlane> symmetry_planes = {};  ///< mirrored by the soil's images
  double boundary_layers = 0.0;  ///< the depth of the ghost layers in spacings, for the images' reach
};

/// The solver setup of a scene of either dimension (Scene or Scene3): the kernel, the time step and
/// the stage parameters from its settings, the rest from `parts`.
template <int dim, class Scene>
SolverSetupOf<dim> solver_setup(const Scene& scene, GeometryParts<dim> parts) {
  const auto& g = scene.geometry;
  const SmoothingKernel<dim> kernel(scene.numerics.kernel, g.smoothing_length());
  const InitialSoundSpeeds c = initial_sound_speeds(scene.materials, largest_initial_pressure(scene));
  return {.kernel = kernel,
          .cfl = scene.numerics.cfl,
          .sound_speed = c.largest,
          .end_time = g.end_time,
          .frame_interval = scene.output.frame_interval,
          .momentum = momentum_params(scene.numerics, kernel, g.gravity, g.particle_spacing, c.largest),
          .guard = std::move(parts.guard),
          .walls = std::move(parts.walls),
          .potential_datum = parts.potential_datum,
          .kinematics = {.corrected = scene.numerics.velocity_gradient_correction,
                         .density_diffusion =
                             scene.numerics.density_diffusion * kernel.smoothing_length() * c.largest},
          .pressure_dependent_stiffness = c.pressure_dependent,
          .rest = scene.rest,
          .domain = parts.domain,
          .checkpoint_interval = scene.output.checkpoint_interval,
          .constant_stiffness_sound_speed = c.constant_stiffness,
          .ghost_body_force = scene.numerics.ghost_body_force ? g.gravity : Vec<dim>{},
          .symmetry_planes = std::move(parts.symmetry_planes),
          .image_reach = image_reach(kernel, parts.boundary_layers * g.particle_spacing)};
}

}  // namespace soilsph::sph
