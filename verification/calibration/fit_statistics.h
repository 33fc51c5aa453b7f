#pragma once
/// @file
/// What the fit says about its parameters, from the linearisation at the optimum (Bates & Watts,
/// Nonlinear Regression Analysis, 1988, §2.3): with J = ∂r/∂z the Jacobian in the optimiser's
/// coordinates, N residuals and p parameters,
///
///     s² = ‖r‖² / (N − p),   Cov(z) = s² (JᵀJ)⁻¹,   Cov(x) = D Cov(z) D,  D = diag(dx_k/dz_k),
///
/// the last by the chain rule through the scaling (parameter_scaling.h); standard errors are the
/// square roots of the diagonal, correlations Cov_ij / (σ_i σ_j), and 95 % intervals
/// x ± t_{0.975, N−p} σ (Student's t).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "verification/calibration/calibration_file.h"
#include "verification/calibration/parameter_scaling.h"

namespace soilsph::calibration {

/// Warn when |correlation| exceeds this: the data barely tell the two parameters apart.
inline constexpr double kStrongCorrelation = 0.95;
/// A value within this fraction of its bounds' span from a bound sits on it.
inline constexpr double kOnBound = 1e-6;

struct ParameterEstimate {
  std::string key;
  double value = 0.0;
  double standard_error = 0.0;  ///< +∞ when the data do not determine it (JᵀJ singular)
  double lower_95 = 0.0, upper_95 = 0.0;
  double lower_bound = 0.0, upper_bound = 0.0;
  double start = 0.0;
  bool on_bound = false;
};

struct FitStatistics {
  std::vector<ParameterEstimate> parameters;
  Eigen::MatrixXd covariance;  ///< of the physical parameters
  Eigen::MatrixXd correlation;
  double cost = 0.0;               ///< ‖r‖², the sum of squared normalised residuals
  long residuals = 0;              ///< N
  long degrees_of_freedom = 0;     ///< N − p
  double residual_variance = 0.0;  ///< s²
  double t_95 = 0.0;               ///< t_{0.975, N−p}
  std::vector<std::string> warnings;
};

FitStatistics fit_statistics(const std::vector<FitParameter>& parameters,
                             const std::vector<ParameterScaling>& scalings, const Eigen::VectorXd& z,
                             const Eigen::VectorXd& residuals, const Eigen::MatrixXd& jacobian);

}  // namespace soilsph::calibration
