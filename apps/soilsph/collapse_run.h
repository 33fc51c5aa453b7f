#pragma once
/// @file
/// What `soilsph collapse` shares between scenes of the plane (collapse_command.cpp) and of space
/// (collapse_3d_command.cpp): its options, the thread tuner, the run's folder and its clean start, and
/// how a run stopped by a signal ends.
#include <filesystem>
#include <string>
#include <vector>

#include "apps/soilsph/stop_signal.h"
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

/// `--threads auto` or `--threads N` (collapse_command.cpp).
sph::ThreadTuner thread_tuner(const std::string& option);
/// Removes what a previous run left in DIR that would describe it beside this run's frames.
void remove_stale_results(const std::filesystem::path& dir);
/// The run's folder: --resume's, --out, or results/<the scene file's stem>.
std::filesystem::path run_folder(const CollapseOptions& o);

/// Why a run stopped, as summary.json's stop_reason says it: "at rest", "end time" or "signal SIGTERM".
std::string stop_reason(const sph::RunStatistics& stats, const StopSignal& signal);
/// A run stopped by a signal says where it is saved and how to go on, and exits with 128 + the signal
/// (throws ExitCode); any other stop returns.
void exit_if_stopped_by_signal(const sph::RunStatistics& stats, const StopSignal& signal,
                               const std::filesystem::path& dir);

/// Runs a scene of space (collapse_3d_command.cpp): frames, checkpoints, summary.json and a short
/// report in DIR; with CollapseOptions::resume, continues the run DIR's checkpoint saved.
void run_collapse_3d(const CollapseOptions& o, const sph::Scene3& scene, const std::filesystem::path& dir);

}  // namespace soilsph::cli
