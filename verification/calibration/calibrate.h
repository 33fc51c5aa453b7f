#pragma once
/// @file
/// A calibration from file to answer: the fit from the material's values (and from random starts
/// inside the bounds, when asked), the best one's statistics, the misfit of each experiment's
/// columns, and the fitted and starting curves at the readings.
#include <string>
#include <vector>

#include "verification/calibration/calibration_file.h"
#include "verification/calibration/fit_statistics.h"
#include "verification/calibration/least_squares.h"
#include "verification/calibration/residuals.h"

namespace soilsph::calibration {

/// The fitted model against one measured column.
struct ColumnMisfit {
  std::size_t experiment = 0;
  std::string column;
  double rms = 0.0;             ///< root-mean-square of model − measured, SI (Pa or 1)
  double range = 0.0;           ///< the measured range, SI
  double rms_normalised = 0.0;  ///< rms / range
};

/// One start's run of the optimiser.
struct StartRun {
  std::vector<double> start;  ///< physical values
  LeastSquaresResult fit;
};

struct Calibration {
  std::vector<StartRun> starts;
  std::size_t best = 0;        ///< the start with the lowest cost
  std::vector<double> values;  ///< fitted, physical, in the order of the file's parameters
  FitStatistics statistics;
  std::vector<ColumnMisfit> misfits;
  std::vector<ModelCurve> fitted, initial;  ///< at the readings, per experiment
  toml::table material;                     ///< the calibrated [material] table
  long evaluations = 0;                     ///< model evaluations (each runs every experiment), all starts
  double seconds = 0.0;                     ///< wall time of the fit
};

/// The random starts are drawn uniformly in the scaled coordinate u (ln x for positive bounds),
/// over the middle 80 % of the bounds, from the file's seed. A start at which the model cannot run
/// every experiment is refused with the run's message (ParameterError naming the experiment) for
/// the material's own values, and skipped for a random start.
Calibration calibrate(const CalibrationFile& file);

}  // namespace soilsph::calibration
