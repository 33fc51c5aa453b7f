#include "verification/calibration/least_squares.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <atomic>
#include <exception>
#include <memory>
#include <stdexcept>

namespace soilsph::calibration {

namespace {

/// Residual of a trial the model cannot run: far above any normalised residual (those are O(1)),
/// so the step is rejected.
constexpr double kFailedResidual = 1e6;
/// Central-difference step of the final Jacobian (the statistics'): truncation error ~h² = 1e-8
/// relative, well above the round-off of runs converged to 1e-10 or better.
constexpr double kCentralStep = 1e-4;

Eigen::Map<const Eigen::VectorXd> view(const gsl_vector* v) {
  return {v->data, static_cast<Eigen::Index>(v->size)};  // GSL vectors here have stride 1
}

struct Problem {
  const ResidualFunction& r;
  const LeastSquaresOptions& options;
  std::size_t size;
  long evaluations = 0;
  Eigen::VectorXd last_z{}, last_r{};  ///< the last trial, from which GSL asks for the Jacobian
  std::vector<Iterate> history{};
  std::exception_ptr error{};  ///< an exception other than a failed run, rethrown after GSL returns
};

bool evaluate(const ResidualFunction& r, const Eigen::VectorXd& z, Eigen::VectorXd& out) {
  return r(z, out) && out.allFinite();
}

int residual_callback(const gsl_vector* x, void* data, gsl_vector* f) {
  auto& p = *static_cast<Problem*>(data);
  try {
    p.last_z = view(x);
    ++p.evaluations;
    if (!evaluate(p.r, p.last_z, p.last_r))
      p.last_r = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(p.size), kFailedResidual);
  } catch (...) {
    p.error = std::current_exception();
    return GSL_EFAILED;
  }
  Eigen::Map<Eigen::VectorXd>(f->data, static_cast<Eigen::Index>(f->size)) = p.last_r;
  return GSL_SUCCESS;
}

int jacobian_callback(const gsl_vector* x, void* data, gsl_matrix* J) {
  auto& p = *static_cast<Problem*>(data);
  try {
    const Eigen::VectorXd z = view(x);
    Eigen::VectorXd rz = p.last_r;
    if (z != p.last_z) {
      ++p.evaluations;
      if (!evaluate(p.r, z, rz))
        throw std::runtime_error("the Jacobian was asked at a point the model cannot run");
    }
    const Eigen::MatrixXd jacobian = difference_jacobian(p.r, z, rz, p.options.difference_step, false,
                                                         p.options.concurrent, p.evaluations);
    for (Eigen::Index i = 0; i < jacobian.rows(); ++i)
      for (Eigen::Index j = 0; j < jacobian.cols(); ++j) gsl_matrix_set(J, i, j, jacobian(i, j));
  } catch (...) {
    p.error = std::current_exception();
    return GSL_EFAILED;
  }
  return GSL_SUCCESS;
}

void iteration_callback(const std::size_t iteration, void* data, const gsl_multifit_nlinear_workspace* w) {
  auto& p = *static_cast<Problem*>(data);
  const Eigen::VectorXd f = view(gsl_multifit_nlinear_residual(w));
  p.history.push_back({static_cast<int>(iteration), f.squaredNorm(), view(gsl_multifit_nlinear_position(w))});
}

std::string stop_reason(int status, int info) {
  if (status == GSL_SUCCESS)
    return info == 1 ? "converged: the step is below the tolerance"
                     : "converged: the gradient is below the tolerance";
  if (status == GSL_EMAXITER) return "stopped: max_iterations reached before convergence";
  if (status == GSL_ENOPROG)
    return "stopped: no step reduces the misfit further (at the precision of the model runs)";
  return std::string("stopped: ") + gsl_strerror(status);
}

}  // namespace

Eigen::MatrixXd difference_jacobian(const ResidualFunction& r, const Eigen::VectorXd& z,
                                    const Eigen::VectorXd& rz, double step, bool central, bool concurrent,
                                    long& evaluations) {
  const auto n = z.size();
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(rz.size(), n);
  std::atomic<long> count = 0;
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic) if (concurrent)
  for (Eigen::Index j = 0; j < n; ++j) {
    try {
      const double h = step * std::max(1.0, std::abs(z(j)));
      const auto at = [&](double offset, Eigen::VectorXd& out) {
        Eigen::VectorXd shifted = z;
        shifted(j) += offset;
        ++count;
        return evaluate(r, shifted, out);
      };
      Eigen::VectorXd forward, backward;
      const bool has_forward = at(h, forward);
      const bool has_backward = (central || !has_forward) && at(-h, backward);
      if (has_forward && has_backward)
        jacobian.col(j) = (forward - backward) / (2.0 * h);
      else if (has_forward)
        jacobian.col(j) = (forward - rz) / h;
      else if (has_backward)
        jacobian.col(j) = (rz - backward) / h;
    } catch (...) {
#pragma omp critical(soilsph_jacobian_error)
      error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  evaluations += count;
  return jacobian;
}

LeastSquaresResult least_squares(const ResidualFunction& r, std::size_t size, const Eigen::VectorXd& start,
                                 const LeastSquaresOptions& options) {
  const auto n = static_cast<std::size_t>(start.size());
  Problem problem{.r = r, .options = options, .size = size};
  gsl_multifit_nlinear_parameters parameters = gsl_multifit_nlinear_default_parameters();
  parameters.trs =
      options.method == TrustRegion::Dogleg ? gsl_multifit_nlinear_trs_dogleg : gsl_multifit_nlinear_trs_lm;
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residual_callback;
  fdf.df = jacobian_callback;
  fdf.n = size;
  fdf.p = n;
  fdf.params = &problem;
  const std::unique_ptr<gsl_multifit_nlinear_workspace, decltype(&gsl_multifit_nlinear_free)> workspace(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &parameters, size, n),
      gsl_multifit_nlinear_free);
  gsl_vector_const_view x0 = gsl_vector_const_view_array(start.data(), n);
  // GSL's default handler aborts; its status codes are handled here instead.
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  int info = 0;
  int status = gsl_multifit_nlinear_init(&x0.vector, &fdf, workspace.get());
  if (status == GSL_SUCCESS)
    status = gsl_multifit_nlinear_driver(static_cast<std::size_t>(options.max_iterations), options.tolerance,
                                         options.tolerance * options.tolerance, 0.0, iteration_callback,
                                         &problem, &info, workspace.get());
  gsl_set_error_handler(previous);
  if (problem.error) std::rethrow_exception(problem.error);
  LeastSquaresResult result;
  result.z = view(gsl_multifit_nlinear_position(workspace.get()));
  if (!evaluate(r, result.z, result.residuals))
    throw std::runtime_error("the model cannot be run at the fit's end point");
  ++problem.evaluations;
  result.jacobian = difference_jacobian(r, result.z, result.residuals, kCentralStep, true, options.concurrent,
                                        problem.evaluations);
  result.history = std::move(problem.history);
  result.converged = status == GSL_SUCCESS;
  result.stop = stop_reason(status, info);
  result.evaluations = problem.evaluations;
  return result;
}

}  // namespace soilsph::calibration
