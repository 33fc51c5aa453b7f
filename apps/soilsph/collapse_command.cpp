// `soilsph collapse SCENE.toml [--out DIR] [--threads N|auto] [--set KEY=VALUE]...`: the SPH soil-column
// collapse (sph/): reads the scene, runs the solver, writes frames, summary.json and a short report.
#include <omp.h>

#include <algorithm>
#include <charconv>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "sph/collapse.h"
#include "sph/diagnostics.h"
#include "sph/frame_buffers.h"
#include "sph/output/frame_writer.h"
#include "sph/output/progress.h"
#include "sph/output/summary.h"

namespace soilsph::cli {

namespace {
/// `--threads auto`: every core (or OMP_NUM_THREADS if less), one thread while the machine is too busy for
/// more to help (sph/thread_tuner.h); `--threads N`: N throughout, capped at the core count, since more
/// threads than cores only wait for each other at every barrier of a step.
sph::ThreadTuner thread_tuner(const std::string& option) {
  const int cores = omp_get_num_procs();
  if (option == "auto") return sph::ThreadTuner(std::min(omp_get_max_threads(), cores), true);
  int requested = 0;
  const auto [end, ec] = std::from_chars(option.data(), option.data() + option.size(), requested);
  if (ec != std::errc() || end != option.data() + option.size() || requested < 1)
    throw std::runtime_error("--threads " + option + ": expected \"auto\" or a whole number of threads >= 1");
  if (requested > cores)
    std::cerr << "soilsph collapse: --threads " << requested << " capped at the " << cores
              << " cores of this machine\n";
  return sph::ThreadTuner(std::min(requested, cores), false);
}

struct CollapseOptions {
  std::string scene;
  std::string out = "results/collapse";
  std::string threads = "auto";  ///< "auto" or a count
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
  const ThreadTuner tuner = thread_tuner(o.threads);

  Collapse collapse(scene);
  const Particles& particles = collapse.particles();
  const SolverSetup& setup = collapse.setup();
  std::cout << o.scene << ": " << model_name(scene.material) << ", " << particles.soil_count << " soil + "
            << particles.boundary_count() << " boundary particles, h = " << setup.kernel.smoothing_length()
            << " m, c = " << setup.sound_speed << " m/s, dt = " << setup.initial_time_step()
            << " s at rest, to t = " << scene.geometry.end_time << " s"
            << (scene.rest.enabled ? " or rest, " : ", ") << tuner.threads() << " thread(s)"
            << (o.threads == "auto" ? " (auto: fewer while they are slower)" : "") << std::endl;

  FrameWriter writer(o.out, scene.output.fields);
  FrameBuffers buffers;
  Progress progress(scene.geometry.end_time);
  const auto on_frame = [&](const Particles& p, double t) {
    if (!all_finite(p))
      throw std::runtime_error("the solution is no longer finite at t = " + std::to_string(t) + " s");
    writer.write(buffers.view(p, t, scene.output.fields));
  };
  const auto on_step = [&](double t, std::size_t steps) { progress.update(t, steps); };
  const RunStatistics stats = collapse.run(tuner, on_frame, on_step);
  progress.finish();
  const DepositMetrics deposit = collapse.deposit();
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
  s.runout_thick_m = deposit.runout_thick_m;
  s.max_speed_end = max_speed(particles);
  s.kinetic_energy_end = kinetic_energy(particles);
  s.particle_spacing = scene.geometry.particle_spacing;
  s.smoothing_ratio = scene.geometry.smoothing_ratio;
  s.time_step = setup.initial_time_step();
  s.smallest_time_step = stats.smallest_time_step;
  s.largest_time_step = stats.largest_time_step;
  s.stopped_at_rest = stats.stopped_at_rest;
  s.guard_corrections = stats.guard_corrections;
  s.fallback_stress_updates = stats.fallback_stress_updates;
  s.threads = tuner.threads();
  write_summary_json(std::filesystem::path(o.out) / "summary.json", s);
  if (stats.stopped_at_rest)
    std::cout << "at rest at t = " << stats.end_time << " s after " << stats.steps << " steps\n";
  std::cout << "runout " << s.runout_m << " m (" << s.runout_thick_m << " m where H0/10 thick), height "
            << s.height_m << " m, repose angle " << s.repose_angle_deg << " deg, max speed at end "
            << s.max_speed_end << " m/s, wall guard acted " << stats.guard_corrections << " times, "
            << stats.fallback_stress_updates << " stress updates needed a fallback (stages/stress_update.h)\n"
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
  cmd->add_option("--threads", o->threads,
                  "threads: a number (at most the cores), or auto: every core, one while the machine is too "
                  "busy for more to help")
      ->capture_default_str();
  cmd->add_option("--set", o->overrides, "override a scene value, e.g. --set scene.particle_spacing=0.002")
      ->take_all()
      ->allow_extra_args(false);
  cmd->callback([o] { run_collapse(*o); });
}

}  // namespace soilsph::cli
