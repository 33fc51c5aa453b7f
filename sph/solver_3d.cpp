#include <vector>

#include "sph/initial_state_3d.h"
#include "sph/setup_parts.h"
#include "sph/solver.h"

namespace soilsph::sph {

SolverSetupOf<3> make_solver_setup(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  const CubicSplineKernel<3> kernel(g.smoothing_length());
  const InitialSoundSpeeds c = initial_sound_speeds(scene.materials, largest_initial_pressure(scene));
  PlaneGuard guard;
  for (const Wall3& wall : g.walls) guard.add(wall.plane, g.boundary_layers * g.particle_spacing);
  return {.kernel = kernel,
          .cfl = scene.numerics.cfl,
          .sound_speed = c.largest,
          .end_time = g.end_time,
          .frame_interval = scene.output.frame_interval,
          .momentum = momentum_params(scene.numerics, kernel, g.gravity, g.particle_spacing, c.largest),
          .guard = guard,
          .walls = {},  // the walls of space stay where they are built
          .potential_datum = g.floor_level,
          .velocity_gradient_correction = scene.numerics.velocity_gradient_correction,
          .pressure_dependent_stiffness = c.pressure_dependent,
          .rest = scene.rest,
          .domain = g.domain,
          .checkpoint_interval = scene.output.checkpoint_interval,
          .constant_stiffness_sound_speed = c.constant_stiffness,
          .ghost_body_force = scene.numerics.ghost_body_force ? g.gravity : Vec3{}};
}

}  // namespace soilsph::sph
