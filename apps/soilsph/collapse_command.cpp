// `soilsph collapse SCENE.toml [--out DIR] [--threads N|auto] [--set KEY=VALUE]...` and
// `soilsph collapse --resume DIR [--set scene.end_time=T]...`: the SPH soil-column collapse (sph/):
// reads the scene, runs the solver, writes frames, checkpoints, summary.json and a short report.
// What each file of DIR holds after a normal end, a signal, kill -9, a blow-up and a full disk is in
// docs/reference/output-formats.md.
#include <algorithm>
#include <iostream>
#include <limits>

#include "apps/soilsph/collapse_preparation.h"
#include "apps/soilsph/collapse_run.h"
#include "apps/soilsph/commands.h"
#include "apps/soilsph/stop_signal.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/models/loosening.h"
#include "soilsph/version.h"
#include "sph/collapse.h"
#include "sph/diagnostics.h"
#include "sph/feasibility.h"
#include "sph/output/checkpoint.h"
#include "sph/output/histories.h"
#include "sph/output/summary.h"

namespace soilsph::cli {
namespace fs = std::filesystem;

namespace {

/// The keys `--resume` may change: when and how the run ends and how often it saves itself. Any
/// other change would not continue the same run.
constexpr std::string_view kResumableKeys[] = {"scene.end_time",      "scene.stop_at_rest",
                                               "scene.rest_speed",    "scene.rest_duration",
                                               "scene.rest_fraction", "scene.max_run_hours",
                                               "output.checkpoint_interval"};

void check_resumable(const std::vector<std::string>& overrides) {
  for (const std::string& assignment : overrides) {
    const std::string key = assignment.substr(0, assignment.find('='));
    if (std::find(std::begin(kResumableKeys), std::end(kResumableKeys), key) == std::end(kResumableKeys)) {
      std::string allowed;
      for (std::string_view k : kResumableKeys) allowed.append(allowed.empty() ? "" : ", ").append(k);
      throw ParameterError("--set " + assignment + ": " + key +
                           " cannot change when a run is resumed (it would not continue the same run; start a "
                           "new one). Allowed with --resume: " + allowed);
    }
  }
}

template <class Model>
std::string integrator_of(const Model& model) {
  if constexpr (requires { model.integrator(); }) {
    return std::string(integrator_name(model.integrator()));
  } else {
    return "none";
  }
}

/// Says which UMAT plug-ins run their calls one at a time (thread_safe = false) on several threads.
void note_serialised_umats(const sph::Scene& scene, int threads) {
  for (std::size_t k = 0; k < scene.materials.size(); ++k)
    if (const auto* umat = std::get_if<UmatModel>(&scene.materials[k]); umat && !umat->params().thread_safe && threads > 1)
      std::cerr << "note: material " << scene.material_names[k] << ": the UMAT " << umat->params().library
                << " is not declared thread-safe (thread_safe = false): its calls run one at a time\n";
}

/// The summary's record of the run: what it is, where it came from, and (after a stop) its figures.
sph::Summary describe(const sph::Scene& scene, const sph::Collapse& collapse, int threads) {
  sph::Summary s;
  std::vector<std::string> models, integrators;  // the distinct ones, in the materials' order
  const auto join = [](std::string& to, std::vector<std::string>& seen, const std::string& name) {
    if (std::find(seen.begin(), seen.end(), name) != seen.end()) return;
    to += (seen.empty() ? "" : " + ") + name;
    seen.push_back(name);
  };
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const Material& m = scene.materials[k];
    const std::string model(model_name(m)), integrator = std::visit([](const auto& x) { return integrator_of(x); }, m);
    join(s.model, models, model);
    join(s.integrator, integrators, integrator);
    const auto& kind = collapse.particles().material;
    s.materials.push_back({scene.material_names[k], model, integrator,
                           static_cast<std::size_t>(std::count(kind.begin(), kind.end(), static_cast<int>(k)))});
  }
  s.particles = collapse.particles().soil_count;
  s.boundary_particles = collapse.particles().boundary_count();
  s.particle_spacing = scene.geometry.particle_spacing;
  s.smoothing_ratio = scene.geometry.smoothing_ratio;
  s.time_step = collapse.setup().initial_time_step();
  s.threads = threads;
  s.version = kVersion;
  s.command_line = invocation();
  s.inputs_json = sph::scene_json(scene);
  s.boundaries = scene.geometry.layout.walls;
  s.initial_stress = initial_stress_record(scene.initial.stress, collapse.gravity_loading());
  return s;
}

/// Adds the time loop's statistics: all a failed run can report (its particles may lie anywhere).
void add_statistics(sph::Summary& s, const sph::RunStatistics& stats, std::size_t soil_count) {
  s.steps = stats.steps;
  s.end_time = stats.end_time;
  s.wall_seconds = stats.wall_seconds;
  s.particle_steps_per_second =
      stats.wall_seconds > 0
          ? static_cast<double>(soil_count) * static_cast<double>(stats.steps) / stats.wall_seconds
          : 0.0;
  s.smallest_time_step = stats.smallest_time_step;
  s.largest_time_step = stats.largest_time_step;
  s.stopped_at_rest = stats.stopped_at_rest;
  s.guard_corrections = stats.guard_corrections;
  s.fallback_stress_updates = stats.fallback_stress_updates;
}

/// A failed run's deposit measures: none (null in summary.json), its particles may lie anywhere.
void clear_deposit(sph::Summary& s) {
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  s.runout_m = s.height_m = s.repose_angle_deg = s.runout_thick_m = none;
}

/// Adds what a run that stopped reports: statistics, deposit, end state.
void add_results(sph::Summary& s, const sph::RunStatistics& stats, const sph::Collapse& collapse) {
  const sph::Particles& p = collapse.particles();
  const sph::DepositMetrics deposit = collapse.deposit();
  add_statistics(s, stats, p.soil_count);
  s.runout_m = deposit.runout_m;
  s.height_m = deposit.height_m;
  s.repose_angle_deg = deposit.repose_angle_deg;
  s.runout_thick_m = deposit.runout_thick_m;
  s.max_speed_end = sph::max_speed(p);
  s.kinetic_energy_end = sph::kinetic_energy(p);
}

/// SCENE starts a run, --resume DIR continues one: exactly one of them.
void check_scene_or_resume(const CollapseOptions& o) {
  if (o.resume.empty() == o.scene.empty())
    throw ParameterError(o.scene.empty() ? "soilsph collapse needs a SCENE file, or --resume DIR"
                                         : "soilsph collapse takes a SCENE file or --resume DIR, not both");
}

/// The scene with the --set overrides, of the plane or of space: from its file, or for a resumed run
/// from its checkpoint (only the keys that keep it the same run may change).
sph::AnyScene scene_to_run(const CollapseOptions& o, const fs::path& dir) {
  if (o.resume.empty()) return sph::load_any_scene(o.scene, o.overrides);
  check_resumable(o.overrides);
  const fs::path file = dir / "checkpoint.h5";
  return sph::parse_any_scene(sph::read_checkpoint_scene(file), file.string() + " (scene)", o.overrides);
}

/// The collapse at its start: the scene's particles (relaxed under gravity if it asks), or the
/// checkpoint's. Building the particles refuses a lattice or geostatic state that --set made
/// impossible: say so.
sph::Collapse start_collapse(const sph::Scene& scene, std::optional<sph::Checkpoint>& resumed) {
  return blaming_overrides(scene.overrides,
                           [&] { return cli::start_collapse<sph::Collapse>(scene, resumed); });
}

/// A checkpoint must hold the soil its scene builds.
void check_resumed_particles(const sph::Collapse& collapse, const sph::RunEstimate& estimate,
                             const fs::path& dir) {
  if (collapse.particles().soil_count != estimate.soil_particles)
    throw std::runtime_error((dir / "checkpoint.h5").string() + " holds " +
                             std::to_string(collapse.particles().soil_count) +
                             " soil particles; its scene has " + std::to_string(estimate.soil_particles));
}

/// One line: what runs, how large, to when, for about how long, on how many threads.
void announce_run(const CollapseOptions& o, const sph::Scene& scene, const sph::Collapse& collapse,
                  const sph::RunEstimate& estimate, const sph::ThreadTuner& tuner,
                  const std::optional<sph::Checkpoint>& resumed, const fs::path& dir) {
  const sph::Particles& particles = collapse.particles();
  const sph::SolverSetup& setup = collapse.setup();
  std::cout << (resumed ? dir.string() + " (resumed at t = " + std::to_string(resumed->loop.stats.end_time) +
                              " s)"
                        : o.scene)
            << ": " << describe(scene, collapse, tuner.threads()).model << ", " << particles.soil_count
            << " soil + " << particles.boundary_count()
            << " boundary particles, h = " << setup.kernel.smoothing_length()
            << " m, c = " << setup.sound_speed << " m/s, dt = " << setup.initial_time_step()
            << " s at rest, to t = " << scene.geometry.end_time << " s"
            << (scene.rest.enabled ? " or rest" : "") << " (at most about "
            << sph::human_duration(estimate.seconds) << "), " << tuner.threads() << " thread(s)"
            << (o.threads == "auto" ? " (auto: fewer while they are slower)" : "") << std::endl;
  note_serialised_umats(scene, tuner.threads());
}

/// The summary a run starts with (complete: false, "running"); a resumed run's carries the
/// figures of its checkpoint.
sph::Summary starting_summary(const sph::Scene& scene, const sph::Collapse& collapse, int threads,
                              const std::optional<sph::Checkpoint>& resumed) {
  sph::Summary summary = describe(scene, collapse, threads);
  if (resumed) {
    summary.resumed_from = resumed->loop.stats.end_time;
    add_results(summary, resumed->loop.stats, collapse);
  }
  return summary;
}

/// The summary at the end: the run's figures and why it stopped.
void record_end(sph::Summary& summary, const sph::RunStatistics& stats, const sph::Collapse& collapse,
                const StopSignal& signal, const fs::path& dir) {
  add_results(summary, stats, collapse);
  summary.complete = stats.stop != sph::StopReason::Request;
  summary.stop_reason = stop_reason(stats, signal);
  sph::write_summary_json(dir / "summary.json", summary);
}

/// A soil that loosens without bound (constitutive/models/loosening.h) jostles or scatters after the
/// rest has stopped: say why when the run did not rest.
void warn_if_not_at_rest(const sph::RunStatistics& stats, const sph::Scene& scene) {
  if (!scene.rest.enabled || stats.stopped_at_rest || stats.stop != sph::StopReason::EndTime) return;
  for (const Material& material : scene.materials)
    if (const std::string why =
            std::visit([](const auto& model) { return unbounded_loosening(model); }, material);
        !why.empty())
      std::cerr << "warning: the soil did not come to rest; " << why << '\n';
}

/// The deposit measures, or why a scene has none.
void print_deposit(const sph::Summary& summary, const sph::Scene& scene) {
  if (!scene.deposit.defined) {
    std::cout
        << "deposit (runout, height, repose angle) undefined: add a [deposit] table (origin and direction "
           "of the runout) to measure it";
    return;
  }
  std::cout << "runout " << summary.runout_m << " m (" << summary.runout_thick_m
            << " m where H0/10 thick), height " << summary.height_m << " m, repose angle "
            << summary.repose_angle_deg << " deg";
}

void report_results(const sph::Summary& summary, const sph::RunStatistics& stats, const sph::Scene& scene,
                    const fs::path& dir) {
  if (stats.stopped_at_rest)
    std::cout << "at rest at t = " << stats.end_time << " s after " << stats.steps << " steps\n";
  print_deposit(summary, scene);
  std::cout << ", max speed at end " << summary.max_speed_end << " m/s, wall guard acted "
            << stats.guard_corrections << " times, " << stats.fallback_stress_updates
            << " stress updates needed a fallback (docs/method/sph.md)\n"
            << summary.wall_seconds << " s wall, " << summary.particle_steps_per_second
            << " particle-steps/s; output in " << dir.string() << "/\n";
}

void run_collapse(const CollapseOptions& o) {
  check_scene_or_resume(o);
  const fs::path dir = run_folder(o);
  const sph::AnyScene any = scene_to_run(o, dir);
  if (const auto* space = std::get_if<sph::Scene3>(&any))
    return run_collapse_3d(o, *space, dir);  // chosen once
  const sph::Scene& scene = std::get<sph::Scene>(any);
  std::optional<sph::Checkpoint> resumed = resumed_checkpoint<2>(o, dir);
  const sph::ThreadTuner tuner = thread_tuner(o.threads);
  const sph::RunEstimate estimate = feasible_estimate(scene);
  sph::Collapse collapse = start_collapse(scene, resumed);
  report_gravity_loading(collapse.gravity_loading(), scene.initial.gravity_loading);
  if (resumed) check_resumed_particles(collapse, estimate, dir);
  std::optional<sph::Histories> histories = scene_histories<2>(scene, collapse.particles(), collapse.setup());
  announce_run(o, scene, collapse, estimate, tuner, resumed, dir);

  RunFiles files = open_run_files<2>(dir, scene, resumed);
  sph::Summary summary = starting_summary(scene, collapse, tuner.threads(), resumed);
  sph::write_summary_json(dir / "summary.json", summary);
  const StopSignal signal;
  sph::RunControl control = run_control<2>(files, signal, resumed);
  add_histories<2>(control, histories, dir, scene, resumed);
  const sph::RunStatistics stats =
      run_with_frames(collapse, scene, tuner, files, control,
                      [&](const std::string& why, const std::optional<sph::RunStatistics>& reached) {
                        if (reached) add_statistics(summary, *reached, collapse.particles().soil_count);
                        clear_deposit(summary);
                        summary.stop_reason = why;
                        sph::write_summary_json(dir / "summary.json", summary);
                      });
  record_end(summary, stats, collapse, signal, dir);
  exit_if_stopped_by_signal(stats, signal, dir);
  warn_if_wall_guard_acted(stats, scene);
  warn_if_not_at_rest(stats, scene);
  report_results(summary, stats, scene, dir);
}
}  // namespace

void add_collapse_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("collapse",
                                 "Run an SPH scene: a soil column collapse, a slope, a cut, several soils; "
                                 "frames, checkpoint and summary.json in a folder");
  auto o = std::make_shared<CollapseOptions>();
  cmd->add_option(
         "SCENE", o->scene,
         "scene file (TOML: [scene], [initial], [material] or [materials.NAME], [numerics], [output], "
         "and optionally [[regions]], [[boundaries]], [deposit], [[gauges]]; soilsph examples lists "
         "the shipped ones)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out,
                  "output folder (frames.h5, frames.xdmf, checkpoint.h5, scene.toml, summary.json); default: "
                  "results/ and the scene file's name without .toml");
  cmd->add_option(
         "--resume", o->resume,
         "continue the run in this folder from its checkpoint.h5 (with --set scene.end_time=T to run "
         "further); frames are appended there")
      ->check(CLI::ExistingDirectory);
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
