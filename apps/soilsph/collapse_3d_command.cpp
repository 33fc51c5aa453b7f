// `soilsph collapse SCENE.toml` for a scene of space ([scene] dimension = 3): the time loop of
// sph/solver.h in three dimensions (sph/collapse_3d.h), frames in 3D, summary.json with the
// deposit measures of the scene's shape and, for an axisymmetric column, the laws of Lube et al.
// (2004) at its aspect ratio beside them; the histories (boundary forces, gauges, energy),
// checkpoints, a clean stop on a signal and `--resume DIR` as for a scene of the plane
// (collapse_command.cpp).
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>

#include "apps/soilsph/collapse_preparation.h"
#include "apps/soilsph/collapse_run.h"
#include "apps/soilsph/commands.h"
#include "soilsph/version.h"
#include "sph/collapse_3d.h"
#include "sph/output/atomic_file.h"
#include "sph/output/json_text.h"

namespace soilsph::cli {
namespace {
namespace fs = std::filesystem;

/// "name": value lines of a JSON object, in the order added.
class JsonFields {
 public:
  JsonFields& add(const std::string& key, double value) { return raw(key, sph::number(value)); }
  JsonFields& add(const std::string& key, std::size_t value) { return raw(key, std::to_string(value)); }
  JsonFields& add(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  JsonFields& add(const std::string& key, const std::string& value) { return raw(key, sph::quoted(value)); }
  JsonFields& add(const std::string& key, const std::vector<double>& values) {
    std::string list = "[";
    for (std::size_t k = 0; k < values.size(); ++k) list += (k ? ", " : "") + sph::number(values[k]);
    return raw(key, list + "]");
  }
  JsonFields& raw(const std::string& key, const std::string& json) {
    text_ += (text_.empty() ? "{\n  " : ",\n  ") + sph::quoted(key) + ": " + json;
    return *this;
  }
  std::string str() const { return text_ + "\n}\n"; }

 private:
  std::string text_;
};

/// Where a run stands: its statistics so far and whether and why it stopped.
struct RunRecord {
  sph::RunStatistics stats;
  int threads = 1;
  bool complete = false;
  std::string stop_reason;            ///< "running" until it stops
  std::optional<double> resumed_from;  ///< the checkpoint's time (s) of a resumed run
  bool failed = false;                 ///< stopped by an error: its particles may lie anywhere, even at NaN
};

constexpr double kUnmeasured = std::numeric_limits<double>::quiet_NaN();  // null in summary.json

/// The deposit measures of a run, none (null) of a failed one: a blown-up soil has no deposit, and
/// the measures refuse non-finite positions.
sph::AxisymmetricDeposit axisymmetric_deposit(const sph::Collapse3& collapse, const RunRecord& record) {
  if (record.failed) return {kUnmeasured, kUnmeasured, kUnmeasured, kUnmeasured, {}};
  return collapse.axisymmetric_deposit();
}
sph::DepositMetrics slab_deposit(const sph::Collapse3& collapse, const RunRecord& record) {
  if (record.failed) return {kUnmeasured, kUnmeasured, kUnmeasured, kUnmeasured};
  return collapse.slab_deposit();
}

/// The name of a 3D scene's geometry in summary.json.
std::string shape_name(sph::Geometry3::Shape shape) {
  switch (shape) {
    case sph::Geometry3::Shape::AxisymmetricColumn:
      return "axisymmetric-column";
    case sph::Geometry3::Shape::Slab:
      return "slab";
    case sph::Geometry3::Shape::Regions:
      break;
  }
  return "regions";
}

/// The figures of the run and its deposit (docs/reference/output-formats.md, "3D runs").
std::string summary_json(const sph::Scene3& scene, const sph::Collapse3& collapse, const RunRecord& record) {
  const sph::RunStatistics& stats = record.stats;
  const sph::Geometry3& g = scene.geometry;
  const sph::ParticlesOf<3>& p = collapse.particles();
  JsonFields j;
  j.add("dimension", std::size_t{3})
      .add("shape", shape_name(g.shape))
      .add("model", std::string(model_name(scene.material)))
      .add("particles", p.soil_count)
      .add("boundary_particles", p.boundary_count())
      .add("steps", stats.steps)
      .add("end_time", stats.end_time)
      .add("wall_seconds", stats.wall_seconds)
      .add("particle_steps_per_second",
           stats.wall_seconds > 0 ? static_cast<double>(stats.steps * p.soil_count) / stats.wall_seconds : 0.0)
      .add("threads", static_cast<std::size_t>(record.threads))
      .add("stopped_at_rest", stats.stopped_at_rest)
      .add("complete", record.complete)
      .add("stop_reason", record.stop_reason)
      .raw("resumed_from", record.resumed_from ? sph::number(*record.resumed_from) : "null")
      .add("particle_spacing", g.particle_spacing)
      .add("smoothing_ratio", g.smoothing_ratio)
      .add("smallest_time_step", stats.smallest_time_step)
      .add("largest_time_step", stats.largest_time_step)
      .add("guard_corrections", stats.guard_corrections)
      .add("fallback_stress_updates", stats.fallback_stress_updates);
  if (g.shape == sph::Geometry3::Shape::AxisymmetricColumn) {
    const sph::AxisymmetricDeposit d = axisymmetric_deposit(collapse, record);
    const double a = g.column_height / g.column_radius, r0 = g.column_radius;
    j.add("column_radius_m", r0)
        .add("column_height_m", g.column_height)
        .add("aspect_ratio", a)
        .add("azimuth_span_deg", g.azimuth_span_deg)
        .add("runout_radius_m", d.runout_radius_m)
        .add("runout_radius_spread_m", d.runout_radius_spread_m)
        .add("runout_radius_thick_m", d.runout_radius_thick_m)
        .add("height_m", d.height_m)
        .add("sector_runout_m", d.sector_runout_m)
        .add("lube2004_runout_radius_m", r0 * (1.0 + sph::lube2004::runout_ratio(a)))
        .add("lube2004_height_m", r0 * sph::lube2004::height_ratio(a))
        .add("lube2004_time_to_rest_s", sph::lube2004::time_to_rest(g.column_height, g.gravity_magnitude()));
  } else if (g.shape == sph::Geometry3::Shape::Slab) {
    const sph::DepositMetrics d = slab_deposit(collapse, record);
    j.add("runout_m", d.runout_m)
        .add("height_m", d.height_m)
        .add("repose_angle_deg", d.repose_angle_deg)
        .add("runout_thick_m", d.runout_thick_m);
  } else if (g.deposit_measured) {  // regions: the axisymmetric measures from [deposit] axis
    const sph::AxisymmetricDeposit d = axisymmetric_deposit(collapse, record);
    j.add("azimuth_span_deg", g.azimuth_span_deg)
        .add("runout_radius_m", d.runout_radius_m)
        .add("runout_radius_spread_m", d.runout_radius_spread_m)
        .add("runout_radius_thick_m", d.runout_radius_thick_m)
        .add("height_m", d.height_m)
        .add("sector_runout_m", d.sector_runout_m);
  } else {  // regions without [deposit]: no frame to measure from
    for (const char* key : {"azimuth_span_deg", "runout_radius_m", "runout_radius_spread_m",
                            "runout_radius_thick_m", "height_m", "sector_runout_m"})
      j.raw(key, "null");
  }
  if (const std::string initial_stress =
          initial_stress_record(scene.initial.stress, collapse.gravity_loading()).json();
      !initial_stress.empty())
    j.raw("initial_stress", initial_stress);
  j.add("version", std::string(kVersion)).add("command_line", invocation()).raw("inputs", sph::scene_json(scene));
  return j.str();
}

void report(const sph::Scene3& scene, const sph::Collapse3& collapse, const sph::RunStatistics& stats,
            const fs::path& dir) {
  if (stats.stopped_at_rest) std::cout << "at rest at t = " << stats.end_time << " s after " << stats.steps << " steps\n";
  const sph::Geometry3& g = scene.geometry;
  if (g.shape == sph::Geometry3::Shape::Regions && !g.deposit_measured) {
    std::cout << "deposit (runout radius, height) undefined: add a [deposit] table (axis = [x, z])";
  } else if (g.shape != sph::Geometry3::Shape::Slab) {
    const sph::AxisymmetricDeposit d = collapse.axisymmetric_deposit();
    std::cout << "runout radius " << d.runout_radius_m << " m (spread over azimuths "
              << d.runout_radius_spread_m << " m; " << d.runout_radius_thick_m
              << " m where a tenth of the initial height thick), height on the axis " << d.height_m << " m";
  } else {
    const sph::DepositMetrics d = collapse.slab_deposit();
    std::cout << "runout " << d.runout_m << " m, height " << d.height_m << " m, repose angle " << d.repose_angle_deg
              << " deg";
  }
  std::cout << "; wall guard acted " << stats.guard_corrections << " times\n"
            << stats.wall_seconds << " s wall; output in " << dir.string() << "/\n";
}
}  // namespace

void run_collapse_3d(const CollapseOptions& o, const sph::Scene3& scene, const fs::path& dir) {
  const sph::ThreadTuner tuner = thread_tuner(o.threads);
  (void)feasible_estimate(scene);  // refuses a scene it cannot run, before anything is allocated
  std::optional<sph::CheckpointOf<3>> resumed = resumed_checkpoint<3>(o, dir);
  sph::Collapse3 collapse = start_collapse<sph::Collapse3>(scene, resumed);
  report_gravity_loading(collapse.gravity_loading(), scene.initial.gravity_loading);
  std::optional<sph::HistoriesOf<3>> histories = scene_histories<3>(scene, collapse.particles(), collapse.setup());
  std::cout << "soilsph collapse (3D): "
            << (resumed ? "resumed at t = " + std::to_string(resumed->loop.stats.end_time) + " s, " : "")
            << collapse.particles().soil_count << " soil and " << collapse.particles().boundary_count()
            << " boundary particles, up to t = " << scene.geometry.end_time << " s, " << tuner.threads()
            << " thread(s); output in " << dir.string() << "/\n";
  RunFiles files = open_run_files<3>(dir, scene, resumed);
  RunRecord record{.stats = resumed ? resumed->loop.stats : sph::RunStatistics{},
                   .threads = tuner.threads(),
                   .complete = false,
                   .stop_reason = "running",
                   .resumed_from = resumed ? std::optional(resumed->loop.stats.end_time) : std::nullopt};
  const auto write_summary = [&] {
    sph::replace_file(dir / "summary.json", summary_json(scene, collapse, record));
  };
  write_summary();  // says so if killed

  const StopSignal signal;
  sph::RunControlOf<3> control = run_control<3>(files, signal, resumed);
  add_histories<3>(control, histories, dir, scene, resumed);
  record.stats =
      run_with_frames(collapse, scene, tuner, files, control,
                      [&](const std::string& why, const std::optional<sph::RunStatistics>& reached) {
                        if (reached) record.stats = *reached;
                        record.failed = true;
                        record.stop_reason = why;
                        write_summary();
                      });
  record.complete = record.stats.stop != sph::StopReason::Request;
  record.stop_reason = stop_reason(record.stats, signal);
  write_summary();
  exit_if_stopped_by_signal(record.stats, signal, dir);
  warn_if_wall_guard_acted(record.stats, scene);
  report(scene, collapse, record.stats, dir);
}

}  // namespace soilsph::cli
