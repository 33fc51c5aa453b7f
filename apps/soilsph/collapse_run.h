#pragma once
/// @file
/// What `soilsph collapse` shares between scenes of the plane (collapse_command.cpp) and of space
/// (collapse_3d_command.cpp): its options, the thread tuner, the run's folder and its clean start, the
/// checkpoint a resumed run continues, what the time loop reports back, its histories, the run with
/// its frames and progress, and how a run stopped by a signal ends. Each path of the command is a sequence of these
/// steps and its own (collapse_run.cpp for the shared steps that do not depend on the dimension).
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "apps/soilsph/stop_signal.h"
#include "sph/frame_buffers.h"
#include "sph/gravity_loading.h"
#include "sph/output/checkpoint.h"
#include "sph/output/frame_writer.h"
#include "sph/output/histories.h"
#include "sph/output/progress.h"
#include "sph/output/summary.h"
#include "sph/scene_3d.h"
#include "sph/solver.h"
#include "sph/thread_tuner.h"

namespace soilsph::cli {

struct CollapseOptions {
  std::string scene;
  std::string out;               ///< empty: results/<the scene file's stem>
  std::string resume;            ///< a run folder to continue, or empty
  std::string threads = "auto";  ///< "auto" or a count
  std::vector<std::string> overrides;
};

/// `--threads auto` or `--threads N` (collapse_run.cpp).
sph::ThreadTuner thread_tuner(const std::string& option);
/// Removes what a previous run left in DIR that would describe it beside this run's frames.
void remove_stale_results(const std::filesystem::path& dir);
/// The run's folder: --resume's, --out, or results/<the scene file's stem>.
std::filesystem::path run_folder(const CollapseOptions& o);

/// The checkpoint of the run --resume continues from, or nothing for a new run.
template <int dim>
std::optional<sph::CheckpointOf<dim>> resumed_checkpoint(const CollapseOptions& o,
                                                         const std::filesystem::path& dir) {
  if (o.resume.empty()) return std::nullopt;
  return sph::read_checkpoint<dim>(dir / "checkpoint.h5");
}

/// The collapse at its start: the scene's particles, or the checkpoint's (moved out of it).
template <class Collapse, class Scene, class Checkpoint>
Collapse start_collapse(const Scene& scene, std::optional<Checkpoint>& resumed) {
  return resumed ? Collapse(scene, std::move(resumed->particles)) : Collapse(scene);
}

/// What a run writes into its folder as it goes.
struct RunFiles {
  std::filesystem::path dir;
  sph::FrameWriter frames;
  std::string scene_text;  ///< the scene as run, saved in every checkpoint
};

/// The folder's files at the start: nothing of an earlier run may stay beside this one's frames
/// (unless it is the run being continued, from `resumed_at` s), and the scene as run (`scene_text`,
/// TOML) is written first, so that even a run killed at once says what it was.
RunFiles open_run_files(const std::filesystem::path& dir, std::string scene_text, sph::FieldSet fields,
                        int dimension, std::optional<double> resumed_at);

/// The same for a scene of either dimension and the checkpoint it may continue.
template <int dim, class Scene>
RunFiles open_run_files(const std::filesystem::path& dir, const Scene& scene,
                        const std::optional<sph::CheckpointOf<dim>>& resumed) {
  return open_run_files(dir, sph::scene_toml(scene), scene.output.fields, dim,
                        resumed ? std::optional(resumed->loop.stats.end_time) : std::nullopt);
}

/// How the time loop reports back: a stop on a signal, checkpoints into the folder; and where a
/// resumed run continues from.
template <int dim>
sph::RunControlOf<dim> run_control(const RunFiles& files, const StopSignal& signal,
                                   const std::optional<sph::CheckpointOf<dim>>& resumed) {
  sph::RunControlOf<dim> control;
  control.stop_requested = [&signal] { return signal.received() != 0; };
  control.checkpoint = [&files](const sph::ParticlesOf<dim>& p, const sph::LoopState& loop) {
    sph::write_checkpoint(files.dir / "checkpoint.h5", p, loop, files.scene_text);
  };
  if (resumed) control.resume = &resumed->loop;
  return control;
}

/// The histories' samples of the time loop (boundary forces, gauges, energy), into the folder; a
/// resumed run's continue its files.
template <int dim>
void add_histories(sph::RunControlOf<dim>& control, std::optional<sph::HistoriesOf<dim>>& histories,
                   const std::filesystem::path& dir, const sph::SceneOf<dim>& scene,
                   const std::optional<sph::CheckpointOf<dim>>& resumed) {
  if (!histories) return;
  histories->open(dir, resumed ? resumed->loop.stats.end_time : -1.0);
  control.on_sample = [&histories](const sph::StepSampleOf<dim>& s) { (*histories)(s); };
  control.sample_interval = scene.output.history_interval;
  control.first_sample = histories->first_sample();
}

/// Runs the collapse, writing the frames of `scene.output.fields` and progress as it goes; a run that
/// fails calls record_failure(what, reached) (which writes summary.json) before the error is passed
/// on, `reached` holding the statistics up to the last good step (none if it failed before the first).
template <class Collapse, class Scene, class Control, class RecordFailure>
sph::RunStatistics run_with_frames(Collapse& collapse, const Scene& scene, const sph::ThreadTuner& tuner,
                                   RunFiles& files, Control control, RecordFailure&& record_failure) {
  std::optional<sph::RunStatistics> reached;
  control.on_failure = [&reached](const sph::RunStatistics& stats) { reached = stats; };
  sph::FrameBuffers buffers;
  sph::Progress progress(scene.geometry.end_time);
  const int state_variables = sph::frame_state_variables(scene.output, scene.materials);
  const auto on_frame = [&](const auto& p, double t) {
    files.frames.write(buffers.view(p, t, scene.output.fields, state_variables));
  };
  const auto on_step = [&](double t, std::size_t steps) { progress.update(t, steps); };
  try {
    const sph::RunStatistics stats = collapse.run(tuner, on_frame, on_step, control);
    progress.finish();
    return stats;
  } catch (const std::exception& e) {
    progress.finish();
    record_failure(e.what(), reached);
    throw;
  }
}

/// summary.json's "initial_stress" of a run: the scene's [initial] stress method and the relaxation
/// this process ran, if any (none when a run is resumed: its soil was relaxed before t = 0).
sph::InitialStressRecord initial_stress_record(sph::InitialStress method,
                                               const std::optional<sph::GravityLoadingReport>& relaxed);
/// The run log's line on the relaxation, if one ran.
void report_gravity_loading(const std::optional<sph::GravityLoadingReport>& relaxed,
                            const sph::GravityLoading& settings);

/// Why a run stopped, as summary.json's stop_reason says it: "at rest", "end time" or "signal SIGTERM".
std::string stop_reason(const sph::RunStatistics& stats, const StopSignal& signal);
/// A run whose wall guard acted says so on stderr, with what usually cures it.
void warn_if_wall_guard_acted(const sph::RunStatistics& stats, const sph::SceneSettings& scene);
/// A run stopped by a signal says where it is saved and how to go on, and exits with 128 + the signal
/// (throws ExitCode); any other stop returns.
void exit_if_stopped_by_signal(const sph::RunStatistics& stats, const StopSignal& signal,
                               const std::filesystem::path& dir);

/// Runs a scene of space (collapse_3d_command.cpp): frames, checkpoints, summary.json and a short
/// report in DIR; with CollapseOptions::resume, continues the run DIR's checkpoint saved.
void run_collapse_3d(const CollapseOptions& o, const sph::Scene3& scene, const std::filesystem::path& dir);

}  // namespace soilsph::cli
