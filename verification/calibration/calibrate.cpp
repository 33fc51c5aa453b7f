#include "verification/calibration/calibrate.h"

#include <chrono>
#include <cmath>
#include <random>

#include "constitutive/parameters.h"

namespace soilsph::calibration {

namespace {

std::vector<double> physical(const std::vector<ParameterScaling>& scalings, const Eigen::VectorXd& z) {
  std::vector<double> x;
  for (std::size_t k = 0; k < scalings.size(); ++k)
    x.push_back(scalings[k].to_physical(z(static_cast<Eigen::Index>(k))));
  return x;
}

Eigen::VectorXd scaled(const std::vector<ParameterScaling>& scalings, const std::vector<double>& x) {
  Eigen::VectorXd z(static_cast<Eigen::Index>(x.size()));
  for (std::size_t k = 0; k < x.size(); ++k) z(static_cast<Eigen::Index>(k)) = scalings[k].to_scaled(x[k]);
  return z;
}

/// Whether the model may run on several threads at once: not a UMAT that is not declared
/// thread-safe (its SAVE variables and output units are shared by every model that loads it).
bool runs_concurrently(const MaterialTemplate& material) {
  return material.table["model"].value_or(std::string()) != "umat" ||
         material.table["thread_safe"].value_or(false);
}

/// The file's start, then `starts − 1` random ones (calibrate.h).
std::vector<std::vector<double>> starting_points(const CalibrationFile& file,
                                                 const std::vector<ParameterScaling>& scalings) {
  std::vector<std::vector<double>> points{{}};
  for (const FitParameter& p : file.parameters) points[0].push_back(p.start);
  std::mt19937_64 random(file.options.seed);
  std::uniform_real_distribution<double> middle(0.1, 0.9);
  for (int s = 1; s < file.options.starts; ++s) {
    Eigen::VectorXd z(static_cast<Eigen::Index>(scalings.size()));
    for (Eigen::Index k = 0; k < z.size(); ++k) {
      const double fraction = middle(random);
      z(k) = std::log(fraction / (1.0 - fraction));
    }
    points.push_back(physical(scalings, z));
  }
  return points;
}

std::vector<ColumnMisfit> misfits_of(const Residuals& residuals, const std::vector<ModelCurve>& curves) {
  std::vector<ColumnMisfit> misfits;
  const auto& experiments = residuals.file().experiments;
  for (std::size_t e = 0; e < experiments.size(); ++e) {
    const MeasuredCurve& data = experiments[e].data;
    for (std::size_t c = 0; c < data.names.size(); ++c) {
      double sum = 0.0;
      for (std::size_t k = 0; k < data.driven.size(); ++k)
        sum += std::pow(curves[e].columns[c][k] - data.columns[c][k], 2);
      const double rms = std::sqrt(sum / static_cast<double>(data.driven.size()));
      misfits.push_back({.experiment = e,
                         .column = data.names[c],
                         .rms = rms,
                         .range = residuals.range(e, c),
                         .rms_normalised = rms / residuals.range(e, c)});
    }
  }
  return misfits;
}

}  // namespace

Calibration calibrate(const CalibrationFile& file) {
  const auto clock_start = std::chrono::steady_clock::now();
  const Residuals residuals(file);
  const long p = static_cast<long>(file.parameters.size());
  if (static_cast<long>(residuals.size()) <= p)
    throw ParameterError(file.path + ": " + std::to_string(residuals.size()) +
                         " residuals (readings times matched "
                         "columns) for " +
                         std::to_string(p) + " parameters: a fit needs more residuals than parameters");
  std::vector<ParameterScaling> scalings;
  for (const FitParameter& parameter : file.parameters) scalings.emplace_back(parameter);
  const ResidualFunction r = [&](const Eigen::VectorXd& z, Eigen::VectorXd& out) {
    try {
      out = residuals(physical(scalings, z));
      return true;
    } catch (const RunError&) {
      return false;
    }
  };
  Calibration result;
  try {  // the material's own values must run every experiment: say why not, naming it
    result.initial =
        residuals.curves(physical(scalings, scaled(scalings, starting_points(file, scalings)[0])));
  } catch (const RunError& e) {
    throw ParameterError(std::string(e.what()) + " (with the material's values, where the fit starts)");
  }
  const LeastSquaresOptions options{.method = file.options.method,
                                    .max_iterations = file.options.max_iterations,
                                    .tolerance = file.options.tolerance,
                                    .difference_step = file.options.difference_step,
                                    .concurrent = runs_concurrently(file.material)};
  for (const std::vector<double>& start : starting_points(file, scalings)) {
    Eigen::VectorXd r0;
    if (!result.starts.empty() && (++result.evaluations, !r(scaled(scalings, start), r0)))
      continue;  // a random start the model refuses
    result.starts.push_back({start, least_squares(r, residuals.size(), scaled(scalings, start), options)});
    result.evaluations += result.starts.back().fit.evaluations;
    if (result.starts.back().fit.residuals.squaredNorm() <
        result.starts[result.best].fit.residuals.squaredNorm())
      result.best = result.starts.size() - 1;
  }
  const LeastSquaresResult& best = result.starts[result.best].fit;
  result.values = physical(scalings, best.z);
  result.statistics = fit_statistics(file.parameters, scalings, best.z, best.residuals, best.jacobian);
  if (!best.converged) result.statistics.warnings.insert(result.statistics.warnings.begin(), best.stop);
  result.fitted = residuals.curves(result.values);
  result.misfits = misfits_of(residuals, result.fitted);
  result.material = file.material.with(result.values);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

}  // namespace soilsph::calibration
