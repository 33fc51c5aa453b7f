#include "sph/gravity_loading.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "sph/diagnostics.h"
#include "sph/initial_state.h"
#include "sph/solver.h"

namespace soilsph::sph {

GravityLoadingReport relax_under_gravity(const Scene& scene, Particles& particles) {
  const GravityLoading& settings = scene.initial.gravity_loading;
  // Every wall in place and still (withdrawn-at-0 walls too), the soil from K0 under its local surface.
  Scene held = scene;
  for (Wall& w : held.geometry.layout.walls) w.motion = WallMotion{};
  Particles q = build_particles(held);
  set_geostatic_state(q, held);
  if (q.soil_count != particles.soil_count) throw std::logic_error("gravity loading: soil particle counts differ");
  SolverSetup setup = make_solver_setup(held);
  setup.end_time = settings.max_time;
  setup.frame_interval = settings.max_time;
  setup.rest.enabled = false;
  setup.checkpoint_interval = 0.0;

  const double g = scene.geometry.gravity_magnitude(), height = scene.geometry.soil_extent.height;
  double mass = 0.0;
  for (std::size_t i = 0; i < q.soil_count; ++i) mass += q.mass[i];
  double heaviest = 0.0;
  for (const Material& m : scene.materials) heaviest = std::max(heaviest, density(m));
  const double energy_scale = mass * g * height, stress_scale = heaviest * g * height;
  std::vector<double> sxx(q.sxx.begin(), q.sxx.begin() + static_cast<std::ptrdiff_t>(q.soil_count));
  std::vector<double> syy(q.syy.begin(), q.syy.begin() + static_cast<std::ptrdiff_t>(q.soil_count));
  std::vector<double> sxy(q.sxy.begin(), q.sxy.begin() + static_cast<std::ptrdiff_t>(q.soil_count));
  GravityLoadingReport report;
  bool settled = false;
  const auto on_step = [&](double t, std::size_t steps) {  // serial, after each step
    double change = 0.0;
    for (std::size_t i = 0; i < q.soil_count; ++i) {
      change = std::max({change, std::abs(q.sxx[i] - sxx[i]), std::abs(q.syy[i] - syy[i]), std::abs(q.sxy[i] - sxy[i])});
      sxx[i] = q.sxx[i], syy[i] = q.syy[i], sxy[i] = q.sxy[i];
    }
    report = {steps, t, kinetic_energy(q) / energy_scale, change / stress_scale};
    // Mass-proportional damping of the half-step velocities (the next kick starts from them).
    const double keep = 1.0 - settings.damping;
    for (std::size_t i = 0; i < q.soil_count; ++i) q.vx[i] *= keep, q.vy[i] *= keep;
    settled = report.kinetic_energy < settings.kinetic_tolerance && report.stress_change < settings.stress_tolerance;
  };
  RunControl control;
  control.stop_requested = [&] { return settled; };
  run_groups(material_groups(held.materials, q), setup, q, [](const Particles&, double) {}, on_step,
             ThreadTuner(omp_get_max_threads(), false), control);
  if (!settled) {
    std::ostringstream msg;
    msg << scene.source << ": [initial] gravity loading did not settle within gravity_loading_max_time = "
        << settings.max_time << " s (" << report.steps << " steps): kinetic energy / (M g H) = " << report.kinetic_energy
        << " (tolerance " << settings.kinetic_tolerance << "), stress change per step / (rho g H) = "
        << report.stress_change << " (tolerance " << settings.stress_tolerance << ")";
    throw std::runtime_error(msg.str());
  }

  // The relaxed soil, at rest, into the scene's particles (soil first in both: the lattice does not
  // depend on the walls).
  for (std::size_t i = 0; i < q.soil_count; ++i) {
    particles.x[i] = q.x[i], particles.y[i] = q.y[i], particles.density[i] = q.density[i];
    particles.x0[i] = q.x[i], particles.y0[i] = q.y[i];  // displacements count from the relaxed soil
    particles.vx[i] = particles.vy[i] = 0.0;
    State s{};
    s.stress = q.state[i].stress;
    s.pc = std::visit(
        [&](const auto& model) {
          return model.initial_preconsolidation(s.stress, scene.initial.overconsolidation_ratio,
                                                scene.initial.preconsolidation_floor);
        },
        scene.materials[static_cast<std::size_t>(q.material[i])]);  // once per particle, before the run
    particles.state[i] = s;
    particles.sxx[i] = s.stress(0, 0), particles.syy[i] = s.stress(1, 1), particles.sxy[i] = s.stress(0, 1);
  }
  return report;
}

}  // namespace soilsph::sph
