#include "sph/solver.h"

#include "sph/initial_state.h"

namespace soilsph::sph {

namespace {
/// The box the soil stays in (blow_up.h): the floor from its far end to the fixed wall and its
/// ghost layers, and twice the column's height, each widened by the kernel support 2h.
Domain domain(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double behind = g.boundary_layers * g.particle_spacing, support = 2.0 * g.smoothing_length();
  return {g.column_width - g.floor_length - behind - support, g.column_width + behind + support,
          -behind - support, 2.0 * g.column_height + support};
}
}  // namespace

SolverSetup make_solver_setup(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const CubicSpline kernel(g.smoothing_length());
  const double rho = density(scene.material);
  // The stiffest elastic state of the column: moduli at the largest initial pressure (constant
  // elasticity ignores it; pressure-dependent MCC is stiffest at the base).
  const Elasticity elasticity = std::visit([](const auto& m) { return m.elasticity(); }, scene.material);
  const double c = p_wave_speed(elasticity.at(largest_initial_pressure(scene)), rho);

  MomentumParams momentum;
  momentum.viscosity_alpha = scene.numerics.viscosity_alpha;
  momentum.viscosity_beta = scene.numerics.viscosity_beta;
  momentum.sound_speed = c;
  momentum.smoothing_length = kernel.smoothing_length();
  momentum.gravity = g.gravity;
  momentum.artificial_stress = {scene.numerics.artificial_stress, scene.numerics.artificial_stress_epsilon,
                                scene.numerics.artificial_stress_exponent, kernel.value(g.particle_spacing)};
  return {kernel,
          scene.numerics.cfl,
          c,
          g.end_time,
          scene.output.frame_interval,
          momentum,
          wall_guard(scene),
          scene.numerics.velocity_gradient_correction,
          elasticity.kind() == Elasticity::Kind::PressureDependent,
          scene.rest,
          domain(scene),
          scene.output.checkpoint_interval};
}

}  // namespace soilsph::sph
