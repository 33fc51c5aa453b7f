#pragma once
/// @file
/// Nonlinear least squares by GSL's trust-region solver (gsl_multifit_nlinear: Levenberg–Marquardt
/// or dogleg), over unbounded scaled coordinates z (parameter_scaling.h), with the Jacobian by
/// forward differences whose columns are evaluated in parallel (OpenMP: one model evaluation per
/// parameter, the costly part of an iteration).
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "verification/calibration/calibration_file.h"

namespace soilsph::calibration {

/// r(z); false when the model cannot be evaluated there. Called from several threads at once unless
/// LeastSquaresOptions::concurrent is false.
using ResidualFunction = std::function<bool(const Eigen::VectorXd& z, Eigen::VectorXd& r)>;

struct LeastSquaresOptions {
  TrustRegion method = TrustRegion::LevenbergMarquardt;
  int max_iterations = 100;
  double tolerance = 1e-10;       ///< GSL's xtol; gtol is its square, ftol 0
  double difference_step = 1e-7;  ///< forward-difference step, times max(1, |z_j|)
  /// Whether r may run on several threads at once; false for a UMAT not declared thread-safe (its
  /// SAVE variables are shared by every model that loads it).
  bool concurrent = true;
};

/// The cost ‖r‖² after an iteration (iteration 0: the start).
struct Iterate {
  int iteration = 0;
  double cost = 0.0;
  Eigen::VectorXd z;
};

struct LeastSquaresResult {
  Eigen::VectorXd z;
  Eigen::VectorXd residuals;
  Eigen::MatrixXd jacobian;  ///< ∂r/∂z at z, by central differences (for the statistics)
  std::vector<Iterate> history;
  bool converged = false;
  std::string stop;      ///< why the iterations ended, in words
  long evaluations = 0;  ///< model evaluations, each a run of every experiment
};

/// Minimises ‖r(z)‖² from `start`; `size` is the number of residuals. A trial where r cannot be
/// evaluated is given residuals so large that the trust region rejects the step and shrinks. The
/// start must be evaluable (std::runtime_error otherwise).
LeastSquaresResult least_squares(const ResidualFunction& r, std::size_t size, const Eigen::VectorXd& start,
                                 const LeastSquaresOptions& options);

/// ∂r/∂z at `z` (with r(z) given), by forward differences in parallel over the columns; a column
/// whose forward step cannot be evaluated takes the backward one, and is 0 if neither can.
/// `central`: central differences (two evaluations per column). `concurrent`: the columns in
/// parallel. Adds to `evaluations`.
Eigen::MatrixXd difference_jacobian(const ResidualFunction& r, const Eigen::VectorXd& z,
                                    const Eigen::VectorXd& rz, double step, bool central, bool concurrent,
                                    long& evaluations);

}  // namespace soilsph::calibration
