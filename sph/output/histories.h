#pragma once
/// @file
/// A run's time histories: at every sample (RunControlOf::on_sample) the force on each boundary
/// present at t = 0 (analysis/boundary_forces.h), the gauges' readings (analysis/gauges.h) and the
/// soil's mechanical energy (analysis/energy.h), written by HistoryWriterOf to boundary_forces.csv,
/// gauges.csv and energy.csv; in the plane or in space.
#include <filesystem>
#include <optional>
#include <type_traits>
#include <vector>

#include "sph/analysis/gauges.h"
#include "sph/output/history_writer.h"
#include "sph/scene.h"
#include "sph/scene_3d.h"
#include "sph/solver.h"

namespace soilsph::sph {

template <int dim>
class HistoriesOf {
 public:
  /// For `scene` with its particles as they start (or as a checkpoint holds them, x0, y0[, z0]
  /// included); throws ParameterError for a gauge outside the soil, before any file is touched.
  HistoriesOf(const SceneOf<dim>& scene, const ParticlesOf<dim>& particles, const SmoothingKernel<dim>& kernel);

  /// Opens the files in `dir`: new ones, or those of a run resumed at `resume_time` (≥ 0).
  void open(const std::filesystem::path& dir, double resume_time = -1.0);
  /// RunControlOf::first_sample after open(): 0 for a new run; after a resume, the sample the run
  /// that saved the checkpoint would have taken next.
  double first_sample() const { return first_sample_; }
  /// One sample (RunControlOf::on_sample), after open().
  void operator()(const StepSampleOf<dim>& s);

 private:
  const SceneOf<dim>& scene_;
  std::vector<std::size_t> walls_;  ///< indices of the walls reported (present at t = 0)
  GaugeSetOf<dim> gauges_;
  std::optional<HistoryWriterOf<dim>> writer_;
  double first_sample_ = 0.0;
};
using Histories = HistoriesOf<2>;

}  // namespace soilsph::sph
