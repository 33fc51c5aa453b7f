#pragma once
/// @file
/// The body of relax_under_gravity (sph/gravity_loading.h), once for the plane and for space:
/// gravity_loading.cpp instantiates it for a Scene, gravity_loading_3d.cpp for a Scene3, each with
/// its dimension's held_still, geostatic_particles and make_solver_setup.
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sph/diagnostics.h"
#include "sph/gravity_loading.h"
#include "sph/solver.h"
#include "sph/stages/pair_vectors.h"

namespace soilsph::sph {

/// The scene as the relaxation runs it: every wall in place and still, a wall withdrawn at t = 0
/// too (in the plane it is in the layout, in space among Geometry3::withdrawn_walls).
Scene held_still(const Scene& scene);
Scene3 held_still(const Scene3& scene);

namespace dynamic_relaxation {

/// The soil's stress components (symmetric_index order), for the change over a step.
template <int dim>
using SoilStress = std::array<std::vector<double>, kSymmetricComponents<dim>>;

template <int dim>
SoilStress<dim> soil_stress(const ParticlesOf<dim>& p) {
  SoilStress<dim> s;
  const auto arrays = stress_arrays(p);
  for (std::size_t c = 0; c < s.size(); ++c)
    s[c].assign(arrays[c]->begin(), arrays[c]->begin() + static_cast<std::ptrdiff_t>(p.soil_count));
  return s;
}

/// max |Δσ_ij| of the soil since `last`, which then holds the stress now.
template <int dim>
double stress_change(const ParticlesOf<dim>& p, SoilStress<dim>& last) {
  const auto now = stress_arrays(p);
  double change = 0.0;
  for (std::size_t c = 0; c < last.size(); ++c)
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      change = std::max(change, std::abs((*now[c])[i] - last[c][i]));
      last[c][i] = (*now[c])[i];
    }
  return change;
}

}  // namespace dynamic_relaxation

template <int dim>
GravityLoadingReport relax_under_gravity(const SceneOf<dim>& scene, ParticlesOf<dim>& particles) {
  const GravityLoading& settings = scene.initial.gravity_loading;
  // Every wall in place and still (withdrawn-at-0 walls too), the soil from K0 under its local surface.
  const SceneOf<dim> held = held_still(scene);
  ParticlesOf<dim> q = geostatic_particles(held);
  if (q.soil_count != particles.soil_count)
    throw std::logic_error("gravity loading: soil particle counts differ");
  SolverSetupOf<dim> setup = make_solver_setup(held);
  setup.end_time = settings.max_time;
  setup.frame_interval = settings.max_time;
  setup.rest.enabled = false;
  setup.checkpoint_interval = 0.0;

  const double g = scene.geometry.gravity_magnitude(), height = soil_height(scene.geometry);
  double mass = 0.0;
  for (std::size_t i = 0; i < q.soil_count; ++i) mass += q.mass[i];
  double heaviest = 0.0;
  for (const Material& m : scene.materials) heaviest = std::max(heaviest, density(m));
  const double energy_scale = mass * g * height, stress_scale = heaviest * g * height;
  dynamic_relaxation::SoilStress<dim> last_stress = dynamic_relaxation::soil_stress(q);
  GravityLoadingReport report;
  bool settled = false;
  const auto on_step = [&](double t, std::size_t steps) {  // serial, after each step
    const double change = dynamic_relaxation::stress_change(q, last_stress);
    report = {steps, t, kinetic_energy(q) / energy_scale, change / stress_scale};
    // Mass-proportional damping of the half-step velocities (the next kick starts from them).
    const double keep = 1.0 - settings.damping;
    for (std::vector<double>* v : q.velocity_arrays())
      for (std::size_t i = 0; i < q.soil_count; ++i) (*v)[i] *= keep;
    settled = report.kinetic_energy < settings.kinetic_tolerance &&
              report.stress_change < settings.stress_tolerance;
  };
  RunControlOf<dim> control;
  control.stop_requested = [&] { return settled; };
  run_groups(
      material_groups(held.materials, q), setup, q, [](const ParticlesOf<dim>&, double) {}, on_step,
      ThreadTuner(omp_get_max_threads(), false), control);
  if (!settled) {
    std::ostringstream msg;
    msg << scene.source << ": [initial] gravity loading did not settle within gravity_loading_max_time = "
        << settings.max_time << " s (" << report.steps
        << " steps): kinetic energy / (M g H) = " << report.kinetic_energy << " (tolerance "
        << settings.kinetic_tolerance << "), stress change per step / (rho g H) = " << report.stress_change
        << " (tolerance " << settings.stress_tolerance << ")";
    throw std::runtime_error(msg.str());
  }

  // The relaxed soil, at rest, into the scene's particles (soil first in both: the lattice does not
  // depend on the walls).
  const auto stress = stress_arrays(particles);
  for (std::size_t i = 0; i < q.soil_count; ++i) {
    particles.x[i] = q.x[i], particles.y[i] = q.y[i], particles.density[i] = q.density[i];
    particles.x0[i] = q.x[i], particles.y0[i] = q.y[i];  // displacements count from the relaxed soil
    if constexpr (dim == 3) particles.z[i] = particles.z0[i] = q.z[i];
    for (std::vector<double>* v : particles.velocity_arrays()) (*v)[i] = 0.0;
    State s{};
    s.stress = q.state[i].stress;
    s.pc = std::visit(
        [&](const auto& model) {
          return model.initial_preconsolidation(s.stress, scene.initial.overconsolidation_ratio,
                                                scene.initial.preconsolidation_floor);
        },
        scene.materials[static_cast<std::size_t>(q.material[i])]);  // once per particle, before the run
    particles.state[i] = s;
    for (int a = 0; a < dim; ++a)  // the plane keeps σxx, σyy and σxy of the 3×3 stress
      for (int b = a; b < dim; ++b) (*stress[symmetric_index<dim>(a, b)])[i] = s.stress(a, b);
  }
  return report;
}

}  // namespace soilsph::sph
