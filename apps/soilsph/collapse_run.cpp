// The steps of `soilsph collapse` that scenes of the plane and of space share and that do not depend
// on the dimension (collapse_run.h).
#include <omp.h>

#include <algorithm>
#include <charconv>
#include <iostream>

#include "apps/soilsph/collapse_run.h"
#include "apps/soilsph/commands.h"
#include "constitutive/parameters.h"
#include "soilsph/version.h"
#include "sph/output/atomic_file.h"
#include "sph/output/histories.h"

namespace soilsph::cli {
namespace fs = std::filesystem;

/// `--threads auto`: every core (or OMP_NUM_THREADS if less), one thread while the machine is too
/// busy for more to help (sph/thread_tuner.h); `--threads N`: N throughout, capped at the core
/// count, since more threads than cores only wait for each other at every barrier of a step.
sph::ThreadTuner thread_tuner(const std::string& option) {
  const int cores = omp_get_num_procs();
  if (option == "auto") return sph::ThreadTuner(std::min(omp_get_max_threads(), cores), true);
  int requested = 0;
  const auto [end, ec] = std::from_chars(option.data(), option.data() + option.size(), requested);
  if (ec != std::errc() || end != option.data() + option.size() || requested < 1)
    throw ParameterError("--threads " + option + ": expected \"auto\" or a whole number of threads >= 1");
  if (requested > cores)
    std::cerr << "soilsph collapse: --threads " << requested << " capped at the " << cores
              << " cores of this machine\n";
  return sph::ThreadTuner(std::min(requested, cores), false);
}

/// Files a previous run left in DIR that would describe it beside this run's frames: its summary,
/// its checkpoint, its histories and the pictures scripts/plot_collapse.py draws.
void remove_stale_results(const fs::path& dir) {
  std::error_code ignored;
  for (const char* name :
       {"summary.json", "summary.json.tmp", "checkpoint.h5", "checkpoint.h5.tmp", "frames.xdmf.tmp",
        "scene.toml.tmp", "deposit.png", "profiles.png", "velocity.png", sph::HistoryWriter::kBoundaryFile,
        sph::HistoryWriter::kGaugeFile, sph::HistoryWriter::kEnergyFile, "boundary_forces.png", "gauges.png",
        "energy.png"})
    fs::remove(dir / name, ignored);
  if (fs::is_directory(dir, ignored))
    for (const auto& entry : fs::directory_iterator(dir, ignored)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("velocity_t") && name.ends_with(".png")) fs::remove(entry.path(), ignored);
    }
}

/// The run's folder: the one --resume continues, --out, or results/<the scene file's stem>, so that
/// runs of different scenes never replace each other.
fs::path run_folder(const CollapseOptions& o) {
  if (!o.resume.empty()) return o.resume;
  if (!o.out.empty()) return o.out;
  return fs::path("results") / fs::path(o.scene).stem();
}

sph::InitialStressRecord initial_stress_record(sph::InitialStress method,
                                               const std::optional<sph::GravityLoadingReport>& relaxed) {
  sph::InitialStressRecord r;
  r.method = method == sph::InitialStress::FlatSurface    ? "flat-surface"
             : method == sph::InitialStress::LocalSurface ? "local-surface"
                                                          : "gravity-loading";
  if (relaxed) {
    r.relaxation_steps = static_cast<long long>(relaxed->steps);
    r.relaxation_kinetic_energy = relaxed->kinetic_energy;
    r.relaxation_stress_change = relaxed->stress_change;
  }
  return r;
}

void report_gravity_loading(const std::optional<sph::GravityLoadingReport>& relaxed,
                            const sph::GravityLoading& settings) {
  if (!relaxed) return;
  std::cout << "gravity loading: settled after " << relaxed->steps << " steps (" << relaxed->time
            << " s of relaxation): kinetic energy / (M g H) = " << relaxed->kinetic_energy << " < "
            << settings.kinetic_tolerance
            << ", stress change per step / (rho g H) = " << relaxed->stress_change << " < "
            << settings.stress_tolerance << "; the run starts from the relaxed soil at rest at t = 0"
            << std::endl;
}

std::string stop_reason(const sph::RunStatistics& stats, const StopSignal& signal) {
  return stats.stop == sph::StopReason::Rest ? "at rest"
         : stats.stop == sph::StopReason::EndTime
             ? "end time"
             : std::string("signal ") + StopSignal::name(signal.received());
}

void warn_if_wall_guard_acted(const sph::RunStatistics& stats, const sph::SceneSettings& scene) {
  if (stats.guard_corrections == 0) return;
  std::cerr << "warning: the wall guard had to push soil particles back through a wall "
            << stats.guard_corrections << " times (0 in a sound run; a smaller [numerics] cfl";
  // A foot compacting over a floor under eq 11 as printed is what the guard holds most
  // (docs/validation/three-dimensions.md); the density diffusion keeps it at its density.
  if (scene.numerics.density_diffusion == 0.0)
    std::cerr << "; where the soil's foot compacts over a floor, [numerics] density_diffusion = 0.1";
  // Soft or overconsolidated MCC sheds grains that soften to dust and are compacted into the floor.
  const bool unbounded_cam_clay = std::ranges::any_of(scene.materials, [](const Material& m) {
    const auto* mcc = std::get_if<ModifiedCamClay>(&m);
    return mcc && mcc->minimum_preconsolidation() == 0.0;
  });
  if (unbounded_cam_clay)
    std::cerr << "; for modified-cam-clay soil a [material] minimum_preconsolidation such as 10 Pa, "
                 "docs/validation/resolution.md";
  std::cerr << ")\n";
}

void exit_if_stopped_by_signal(const sph::RunStatistics& stats, const StopSignal& signal,
                               const fs::path& dir) {
  if (stats.stop != sph::StopReason::Request) return;
  std::cerr << "soilsph collapse: stopped by " << StopSignal::name(signal.received())
            << " at t = " << stats.end_time << " s after " << stats.steps
            << " steps; frames, checkpoint and summary.json are in " << dir.string()
            << "/; continue with: soilsph collapse --resume " << dir.string() << '\n';
  throw ExitCode{128 + signal.received()};
}

RunFiles open_run_files(const fs::path& dir, std::string scene_text, sph::FieldSet fields, int dimension,
                        std::optional<double> resumed_at) {
  if (!resumed_at) remove_stale_results(dir);
  sph::FrameWriter frames = resumed_at ? sph::FrameWriter::continuing(dir, fields, *resumed_at, dimension)
                                       : sph::FrameWriter(dir, fields, dimension);
  sph::replace_file(dir / "scene.toml", "# soilsph collapse: the scene as run, every key resolved (" +
                                            std::string(kVersion) + ")\n# " + invocation() + "\n" +
                                            scene_text);
  return {dir, std::move(frames), std::move(scene_text)};
}

}  // namespace soilsph::cli
