#pragma once
/// @file
/// Adaptive quadrature and bracketed root finding (GSL) for the closed-form references. GSL's abort-on-error
/// handler is switched off; a failure throws std::runtime_error naming the GSL reason.
#include <functional>
#include <optional>

namespace soilsph::verification {

/// ∫_a^b f(x) dx by GSL QAGS (21-point Gauss–Kronrod with Wynn-ε extrapolation, which also handles
/// integrable end-point singularities such as 1/√(b − x)), to relative accuracy `rel_tol`.
double integrate(const std::function<double(double)>& f, double a, double b, double rel_tol = 1e-12);

/// ∫_from^to f(s, s − singular) ds where f ~ 1/|s − singular| (a log singularity just beyond `to`), with
/// `to` between `from` and `singular`. The substitution s = singular + (from − singular) e^{−t} makes the
/// integrand bounded, so QAGS converges right up to the singularity; f also receives the offset
/// s − singular exactly, to evaluate the vanishing factor without cancellation.
double integrate_to_log_singularity(const std::function<double(double, double)>& f, double from, double to,
                                    double singular, double rel_tol = 1e-12);

/// The same integral to depth `depth` = ln((from − singular)/(to − singular)) given directly, for callers
/// that parametrise the approach to the singularity by its logarithmic depth.
double integrate_to_log_depth(const std::function<double(double, double)>& f, double from, double singular,
                              double depth, double rel_tol = 1e-12);

/// The root of f in [lo, hi] (f(lo), f(hi) of opposite signs or zero) by GSL Brent, to `rel_tol` (or
/// `abs_tol`).
double find_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol = 1e-14,
                 double abs_tol = 0.0);

/// The root of f between `regular` and `singular`, where f → +∞ towards `singular` (a log-singular
/// quadrature such as the approach to the critical state): brackets by stepping towards `singular`
/// geometrically (distance /10 per step, down to 1e-11 of the span). Returns nullopt when f is still
/// negative there, i.e. the root is closer to `singular` than resolvable.
std::optional<double> find_root_before_singularity(const std::function<double(double)>& f, double regular,
                                                   double singular, double rel_tol = 1e-14,
                                                   double abs_tol = 0.0);

}  // namespace soilsph::verification
