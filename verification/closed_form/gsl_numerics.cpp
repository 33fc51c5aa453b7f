#include "verification/closed_form/gsl_numerics.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace soilsph::verification {

namespace {
double call(double x, void* f) {
  return (*static_cast<const std::function<double(double)>*>(f))(x);
}

/// Relative error estimate accepted when QAGS reports round-off (near a log singularity).
constexpr double kRoundoffAccepted = 1e-9;

void check(int status, const char* what) {
  if (status != GSL_SUCCESS) throw std::runtime_error(std::string(what) + ": " + gsl_strerror(status));
}

/// Switches GSL's abort-on-error handler off once; status codes are checked instead.
void quiet_gsl() {
  static const bool done = (gsl_set_error_handler_off(), true);
  (void)done;
}
}  // namespace

double integrate(const std::function<double(double)>& f, double a, double b, double rel_tol) {
  quiet_gsl();
  if (a == b) return 0.0;
  constexpr std::size_t kLimit = 1000;
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> work(
      gsl_integration_workspace_alloc(kLimit), gsl_integration_workspace_free);
  gsl_function F{&call, const_cast<std::function<double(double)>*>(&f)};
  double result = 0.0, error = 0.0;
  const int status = gsl_integration_qags(&F, a, b, 0.0, rel_tol, kLimit, work.get(), &result, &error);
  // Next to a log singularity round-off can stop QAGS short of `rel_tol`; its estimate is still good.
  if (status == GSL_EROUND && error <= kRoundoffAccepted * std::abs(result)) return result;
  check(status, "GSL quadrature");
  return result;
}

double integrate_to_log_singularity(const std::function<double(double, double)>& f, double from, double to,
                                    double singular, double rel_tol) {
  return integrate_to_log_depth(f, from, singular, std::log((from - singular) / (to - singular)), rel_tol);
}

double integrate_to_log_depth(const std::function<double(double, double)>& f, double from, double singular,
                              double depth, double rel_tol) {
  const double span = from - singular;
  return integrate(
      [&](double t) {
        const double offset = span * std::exp(-t);  // s − singular
        return -f(singular + offset, offset) * offset;
      },
      0.0, depth, rel_tol);
}

double find_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol,
                 double abs_tol) {
  quiet_gsl();
  const double f_lo = f(lo), f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) == (f_hi < 0.0))
    throw std::runtime_error("GSL root finding: the bracket holds no sign change");
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  gsl_function F{&call, const_cast<std::function<double(double)>*>(&f)};
  check(gsl_root_fsolver_set(solver.get(), &F, lo, hi), "GSL root finding");
  for (int iteration = 0; iteration < 200; ++iteration) {
    check(gsl_root_fsolver_iterate(solver.get()), "GSL root finding");
    const double x_lo = gsl_root_fsolver_x_lower(solver.get());
    const double x_hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(x_lo, x_hi, abs_tol, rel_tol) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw std::runtime_error("GSL root finding: no convergence in 200 iterations");
}

std::optional<double> find_root_before_singularity(const std::function<double(double)>& f, double regular,
                                                   double singular, double rel_tol, double abs_tol) {
  double previous = regular;
  for (int k = 1; k <= 11; ++k) {
    const double x = singular + (regular - singular) * std::pow(10.0, -k);
    if (f(x) >= 0.0) return find_root(f, std::min(previous, x), std::max(previous, x), rel_tol, abs_tol);
    previous = x;
  }
  return std::nullopt;
}

}  // namespace soilsph::verification
