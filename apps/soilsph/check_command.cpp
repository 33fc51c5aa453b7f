// `soilsph check SCENE.toml [--set KEY=VALUE]...`: what a collapse of the scene would be, without
// running it: the particle counts, the memory, the time step and the steps to the end time, the
// estimated run time, and the scene with every key resolved. A scene `collapse` would refuse is
// refused here with the same message (the same steps: apps/soilsph/collapse_preparation.h). A 3D
// scene is built as its collapse starts (sph/collapse_3d.h) and its memory measured on it. Warnings
// (on stderr, exit 0) for what runs but is likely not meant: a 2D scene of regions without
// [deposit], a 3D half or quarter cylinder with a cut plane no mirror closes (sph/cylinder_cuts.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "apps/soilsph/collapse_preparation.h"
#include "apps/soilsph/commands.h"
#include "sph/collapse_3d.h"
#include "sph/cylinder_cuts.h"
#include "sph/solver.h"

namespace soilsph::cli {

namespace {
struct CheckOptions {
  std::string scene;
  std::vector<std::string> overrides;
};

/// The distinct models of the scene's materials, joined by " + " (as summary.json's "model").
std::string models_of(const sph::SceneSettings& scene) {
  std::vector<std::string_view> seen;
  std::string models;
  for (const Material& material : scene.materials) {
    const std::string_view name = model_name(material);
    if (std::ranges::find(seen, name) != seen.end()) continue;
    models += (seen.empty() ? "" : " + ") + std::string(name);
    seen.push_back(name);
  }
  return models;
}

/// Bytes in MB to three digits ("9.33").
std::string megabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", bytes / 1e6);
  return text;
}

template <int dim>
void print_costs(const sph::SceneSettings& scene, double end_time, const sph::ParticlesOf<dim>& particles,
                 const sph::SolverSetupOf<dim>& setup, const sph::RunEstimate& estimate) {
  std::cout << scene.source << ": " << models_of(scene) << (dim == 3 ? ", 3D" : "") << "\n"
            << "  particles: " << particles.soil_count << " soil + " << particles.boundary_count()
            << " boundary\n"
            << "  memory: about " << megabytes(estimate.memory_bytes) << " MB"
            << (dim == 3 ? " (measured on the particles as built and their neighbour list)" : "") << "\n"
            << "  smoothing length h = " << setup.kernel.smoothing_length()
            << " m, P-wave speed c = " << setup.sound_speed
            << " m/s, time step at rest dt = " << setup.initial_time_step() << " s\n"
            << "  end time " << end_time << " s"
            << (scene.rest.enabled ? " (or earlier at rest)" : "") << ": at least "
            << static_cast<long long>(std::ceil(estimate.steps)) << " steps\n"
            << "  run time: at most about " << sph::human_duration(estimate.seconds) << " on one thread (at "
            << sph::kAssumedThroughput << " particle-steps/s)\n";
  if (scene.initial.stress == sph::InitialStress::GravityLoading)
    std::cout << "  the gravity-loading relaxation runs at the start of the collapse (not here)\n";
}

void check_plane(const sph::Scene& scene) {
  const sph::RunEstimate estimate = feasible_estimate(scene);
  const sph::Particles particles = starting_particles(scene);
  const sph::SolverSetup setup = sph::make_solver_setup(scene);
  (void)scene_histories(scene, particles, setup);  // places the gauges, or refuses them
  print_costs(scene, scene.geometry.end_time, particles, setup, estimate);
  // Not an error: a scene of regions runs without deposit measures, but a user who wants them learns
  // it now rather than from the finished run's report.
  if (!scene.deposit.defined)
    std::cerr << "warning: " << scene.source
              << ": no [deposit] table, so the run takes no deposit measures (runout, height, repose angle: "
                 "null in summary.json); add a [deposit] table (origin and direction of the runout) to take "
                 "them\n";
  std::cout << "\n# the scene as it would run, every key resolved\n" << sph::scene_toml(scene);
}

void check_space(const sph::Scene3& scene) {
  (void)feasible_estimate(scene);  // the refusals `collapse` would give, before building anything
  const sph::Collapse3 collapse = blaming_overrides(scene.overrides, [&] { return sph::Collapse3(scene); });
  const sph::RunEstimate estimate = sph::measure_run(collapse.setup(), collapse.particles());
  print_costs(scene, scene.geometry.end_time, collapse.particles(), collapse.setup(), estimate);
  // Not an error: a cut cylinder without its mirror runs, but it is not the part of a symmetric
  // problem its user meant, and the soil leaks out through the cut.
  for (const std::string& cut : sph::open_cylinder_cuts(scene.geometry))
    std::cerr << "warning: " << scene.source << ": " << cut << "\n";
  std::cout << "\n# the scene as it would run, every key resolved\n" << sph::scene_toml(scene);
}

void run_check(const CheckOptions& o) {
  const sph::AnyScene scene = sph::load_any_scene(o.scene, o.overrides);
  if (const auto* space = std::get_if<sph::Scene3>(&scene))
    check_space(*space);
  else
    check_plane(std::get<sph::Scene>(scene));
}
}  // namespace

void add_check_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "check",
      "Check a scene without running it: particle counts, memory, time step, steps, estimated run time "
      "and the scene with every key resolved; refuses what collapse would refuse");
  auto o = std::make_shared<CheckOptions>();
  cmd->add_option("SCENE", o->scene, "scene file (as for soilsph collapse)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", o->overrides, "override a scene value, e.g. --set scene.particle_spacing=0.002")
      ->take_all()
      ->allow_extra_args(false);
  cmd->callback([o] { run_check(*o); });
}

}  // namespace soilsph::cli
