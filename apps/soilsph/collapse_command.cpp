// `soilsph collapse SCENE.toml [--out DIR] [--threads N] [--set KEY=VALUE]...`: the SPH soil-column
// collapse (sph/): reads the scene, runs the solver, writes frames, summary.json and a short report.
#include <omp.h>

#include <iostream>

#include "apps/soilsph/commands.h"
#include "sph/analysis/deposit.h"
#include "sph/diagnostics.h"
#include "sph/frame_buffers.h"
#include "sph/initial_state.h"
#include "sph/output/frame_writer.h"
#include "sph/output/progress.h"
#include "sph/output/summary.h"
#include "sph/solver.h"

namespace soilsph::cli {

namespace {
struct CollapseOptions {
  std::string scene;
  std::string out = "results/collapse";
  int threads = 1;
  std::vector<std::string> overrides;
};

template <class Model>
std::string integrator_of(const Model& model) {
  if constexpr (requires { model.integrator(); }) {
    return std::string(integrator_name(model.integrator()));
  } else {
    return "none";
  }
}

void run_collapse(const CollapseOptions& o) {
  using namespace soilsph::sph;
  const Scene scene = load_scene(o.scene, o.overrides);
  omp_set_num_threads(o.threads);

  Particles particles = build_particles(scene);
  set_geostatic_state(particles, scene);
  const SolverSetup setup = make_solver_setup(scene);
  std::cout << o.scene << ": " << model_name(scene.material) << ", " << particles.soil_count << " soil + "
            << particles.boundary_count() << " boundary particles, h = " << setup.kernel.smoothing_length()
            << " m, c = " << setup.sound_speed << " m/s, dt = " << setup.time_step << " s, " << setup.steps
            << " steps, " << o.threads << " thread(s)" << std::endl;

  FrameWriter writer(o.out, scene.output.fields);
  FrameBuffers buffers;
  Progress progress(scene.geometry.end_time);
  const auto on_frame = [&](const Particles& p, double t) {
    if (!all_finite(p))
      throw std::runtime_error("the solution is no longer finite at t = " + std::to_string(t) + " s");
    writer.write(buffers.view(p, t, scene.output.fields));
  };
  const auto on_step = [&](double t, std::size_t steps) { progress.update(t, steps); };
  const RunStatistics stats = std::visit(
      [&](const auto& model) { return run(model, setup, particles, on_frame, on_step); }, scene.material);
  progress.finish();

  const std::span<const double> x(particles.x.data(), particles.soil_count);
  const std::span<const double> y(particles.y.data(), particles.soil_count);
  const DepositMetrics deposit =
      measure_deposit(x, y, scene.geometry.column_width, scene.geometry.particle_spacing);
  Summary s;
  s.model = std::string(model_name(scene.material));
  s.integrator = std::visit([](const auto& m) { return integrator_of(m); }, scene.material);
  s.particles = particles.soil_count;
  s.boundary_particles = particles.boundary_count();
  s.steps = stats.steps;
  s.end_time = stats.end_time;
  s.wall_seconds = stats.wall_seconds;
  s.particle_steps_per_second =
      static_cast<double>(particles.soil_count) * static_cast<double>(stats.steps) / stats.wall_seconds;
  s.runout_m = deposit.runout_m;
  s.height_m = deposit.height_m;
  s.repose_angle_deg = deposit.repose_angle_deg;
  s.max_speed_end = max_speed(particles);
  s.kinetic_energy_end = kinetic_energy(particles);
  s.particle_spacing = scene.geometry.particle_spacing;
  s.smoothing_ratio = scene.geometry.smoothing_ratio;
  s.time_step = setup.time_step;
  s.threads = o.threads;
  write_summary_json(std::filesystem::path(o.out) / "summary.json", s);
  std::cout << "runout " << s.runout_m << " m, height " << s.height_m << " m, repose angle "
            << s.repose_angle_deg << " deg, max speed at end " << s.max_speed_end << " m/s, wall guard acted "
            << stats.guard_corrections << " times\n"
            << s.wall_seconds << " s wall, " << s.particle_steps_per_second << " particle-steps/s; output in "
            << o.out << "/\n";
}
}  // namespace

void add_collapse_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("collapse", "SPH collapse of a soil column (the paper's section 5)");
  auto o = std::make_shared<CollapseOptions>();
  cmd->add_option("SCENE", o->scene,
                  "scene file (TOML: [scene], [initial], [material], [numerics], [output])")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out, "output folder (frames.h5, frames.xdmf, summary.json)")
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "OpenMP threads")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_option("--set", o->overrides, "override a scene value, e.g. --set scene.particle_spacing=0.002")
      ->take_all()
      ->allow_extra_args(false);
  cmd->callback([o] { run_collapse(*o); });
}

}  // namespace soilsph::cli
