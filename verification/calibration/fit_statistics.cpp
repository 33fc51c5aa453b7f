#include "verification/calibration/fit_statistics.h"

#include <gsl/gsl_cdf.h>
#include <cmath>
#include <limits>

#include "constitutive/parameters.h"

namespace soilsph::calibration {

namespace {

/// (JᵀJ)⁻¹ by the singular values of J: V Σ⁻² Vᵀ; directions whose singular value is below
/// 1e-10 of the largest are not determined by the data and get infinite variance.
Eigen::MatrixXd inverse_normal_matrix(const Eigen::MatrixXd& jacobian) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jacobian, Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(V.rows(), V.rows());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < sigma.size(); ++k) {
    if (sigma(k) > 1e-10 * sigma(0)) {
      inverse += V.col(k) * V.col(k).transpose() / (sigma(k) * sigma(k));
    } else {
      for (Eigen::Index i = 0; i < V.rows(); ++i)
        if (std::abs(V(i, k)) > 1e-8) inverse(i, i) = kInf;
    }
  }
  return inverse;
}

}  // namespace

FitStatistics fit_statistics(const std::vector<FitParameter>& parameters,
                             const std::vector<ParameterScaling>& scalings, const Eigen::VectorXd& z,
                             const Eigen::VectorXd& residuals, const Eigen::MatrixXd& jacobian) {
  FitStatistics s;
  const auto p = static_cast<long>(parameters.size());
  s.residuals = static_cast<long>(residuals.size());
  s.degrees_of_freedom = s.residuals - p;
  s.cost = residuals.squaredNorm();
  s.residual_variance = s.cost / static_cast<double>(s.degrees_of_freedom);
  s.t_95 = gsl_cdf_tdist_Pinv(0.975, static_cast<double>(s.degrees_of_freedom));
  Eigen::VectorXd d(p);
  for (long k = 0; k < p; ++k) d(k) = scalings[k].derivative(z(k));
  s.covariance = d.asDiagonal() * (s.residual_variance * inverse_normal_matrix(jacobian)) * d.asDiagonal();
  s.correlation = Eigen::MatrixXd::Identity(p, p);
  for (long k = 0; k < p; ++k) {
    const FitParameter& f = parameters[k];
    ParameterEstimate e{.key = f.key,
                        .value = scalings[k].to_physical(z(k)),
                        .lower_bound = f.lower,
                        .upper_bound = f.upper,
                        .start = f.start};
    // A parameter the data do not determine has an infinite variance in z; D may make that 0·∞.
    e.standard_error = std::isfinite(s.covariance(k, k)) ? std::sqrt(s.covariance(k, k))
                                                         : std::numeric_limits<double>::infinity();
    e.lower_95 = e.value - s.t_95 * e.standard_error;
    e.upper_95 = e.value + s.t_95 * e.standard_error;
    const double span = f.upper - f.lower;
    e.on_bound = e.value - f.lower < kOnBound * span || f.upper - e.value < kOnBound * span;
    if (e.on_bound)
      s.warnings.push_back(f.key + " = " + format_number(e.value) + " sits on its " +
                           (e.value - f.lower < f.upper - e.value ? "lower" : "upper") + " bound " +
                           format_number(e.value - f.lower < f.upper - e.value ? f.lower : f.upper) +
                           ": the data push it out of [" + format_number(f.lower) + ", " +
                           format_number(f.upper) +
                           "]; widen the bounds or fix it (its standard error assumes it is free)");
    if (!std::isfinite(e.standard_error))
      s.warnings.push_back(f.key + " is not determined by the data (J^T J is singular in its direction)");
    s.parameters.push_back(e);
  }
  for (long i = 0; i < p; ++i)
    for (long j = 0; j < p; ++j)
      if (i != j)
        s.correlation(i, j) = s.covariance(i, j) / std::sqrt(s.covariance(i, i) * s.covariance(j, j));
  for (long i = 0; i < p; ++i)
    for (long j = i + 1; j < p; ++j)
      if (std::abs(s.correlation(i, j)) > kStrongCorrelation)
        s.warnings.push_back(
            parameters[i].key + " and " + parameters[j].key + " are correlated (" +
            format_number(s.correlation(i, j)) +
            "): the data barely tell them apart; fix one or add an experiment that separates them");
  return s;
}

}  // namespace soilsph::calibration
