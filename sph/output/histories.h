#pragma once
/// @file
/// A run's time histories: at every sample (RunControl::on_sample) the force on each boundary
/// present at t = 0 (analysis/boundary_forces.h) and the gauges' readings (analysis/gauges.h),
/// written by HistoryWriter to boundary_forces.csv and gauges.csv.
#include <filesystem>
#include <optional>
#include <vector>

#include "sph/analysis/gauges.h"
#include "sph/output/history_writer.h"
#include "sph/scene.h"
#include "sph/solver.h"

namespace soilsph::sph {

class Histories {
 public:
  /// For `scene` with its particles as they start (or as a checkpoint holds them, x0 and y0
  /// included); throws ParameterError for a gauge outside the soil, before any file is touched.
  Histories(const Scene& scene, const Particles& particles, const CubicSpline& kernel);

  /// Opens the files in `dir`: new ones, or those of a run resumed at `resume_time` (≥ 0).
  void open(const std::filesystem::path& dir, double resume_time = -1.0);
  /// RunControl::first_sample after open(): 0 for a new run; after a resume, the sample the run that
  /// saved the checkpoint would have taken next.
  double first_sample() const { return first_sample_; }
  /// One sample (RunControl::on_sample), after open().
  void operator()(const StepSample& s);

 private:
  const Scene& scene_;
  std::vector<std::size_t> walls_;  ///< indices of the walls reported (present at t = 0)
  GaugeSet gauges_;
  std::optional<HistoryWriter> writer_;
  double first_sample_ = 0.0;
};

}  // namespace soilsph::sph
