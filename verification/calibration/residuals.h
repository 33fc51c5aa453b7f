#pragma once
/// @file
/// The misfit of one set of parameter values: each experiment's programme run by the point driver
/// with the material those values make, its curve interpolated linearly at the measured values of
/// the driven column, and compared column by column with the readings. A residual is
///
///     r = √w (y_model(x_i) − y_i) / (max y − min y),
///
/// the difference normalised by the measured range of its column in its experiment, so that kPa
/// and strains weigh alike and a column counts by its shape, not its unit; w is the experiment's
/// weight. Order: experiment, then matched column, then reading.
#include <Eigen/Dense>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "verification/calibration/calibration_file.h"
#include "verification/point_test.h"

namespace soilsph::calibration {

/// A run that failed or a material the factory refused, named by experiment.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The model's curve at the readings of one experiment: one vector per matched column.
struct ModelCurve {
  std::vector<std::vector<double>> columns;
};

class Residuals {
 public:
  explicit Residuals(const CalibrationFile& file);

  std::size_t size() const { return size_; }
  std::size_t parameters() const { return file_.parameters.size(); }
  /// The residuals at physical `values`; RunError naming the experiment if a run fails.
  /// Safe to call from several threads at once.
  Eigen::VectorXd operator()(std::span<const double> values) const;
  /// The model at the readings of every experiment.
  std::vector<ModelCurve> curves(std::span<const double> values) const;
  /// The measured range by which experiment e's column c is normalised.
  double range(std::size_t e, std::size_t c) const { return ranges_[e][c]; }
  const CalibrationFile& file() const { return file_; }

 private:
  const CalibrationFile& file_;
  std::vector<std::vector<double>> ranges_;
  std::size_t size_ = 0;
};

/// Runs experiment `e`'s programme with `material` (a [material] table) by its own integrator.
verification::PointCurve run_experiment(const Experiment& e, const toml::table& material);

}  // namespace soilsph::calibration
