#pragma once
/// @file
/// The work–precision benchmark of the stress integrators: for each model × load path × integrator
/// × number of increments, the largest error in q and p' against the CVODE reference over the whole
/// path and the CPU time of one path (median of repeats). See docs/method/integrators.md.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "verification/point_test.h"

namespace soilsph::verification {

struct WorkPrecisionRow {
  std::string material, path, integrator;
  int increments;
  double error_q;      ///< max_k |q_k − q_ref,k| / max_k |q_ref,k|
  double error_p;      ///< the same for p'
  double cpu_seconds;  ///< median CPU time of one path
  int repeats;
};

struct WorkPrecisionOptions {
  std::vector<int> increments = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
  /// Schemes; "substep" is run once per tolerance below and labelled e.g. "substep(1e-06)".
  std::vector<std::string> integrators{std::begin(kIntegratorNames), std::end(kIntegratorNames)};
  std::vector<double> substep_tolerances = {1e-4, 1e-6, 1e-8};
  /// "implicit" also runs once per MCC `implicit_tolerance` here (labelled e.g. "implicit(0.001)").
  std::vector<double> implicit_tolerances = {1e-2, 1e-3, 1e-4};
  /// Driver sub-steps (PointTest::path_tolerance): on paths with stress-imposed components (the
  /// triaxial ones) every variant but `explicit` also runs once per tolerance here, labelled e.g.
  /// "implicit(0.0001)+path(1e-05)". Empty (the default): none.
  std::vector<double> path_tolerances;
  double min_seconds = 0.02;  ///< repeat a path until this much CPU time (at least 3, at most 200 times)
};

/// Runs the benchmark on `test` (its `increments` is replaced by each count) for one material.
/// `on_row` is called after each row (for progress output). A material without rate equations (a
/// UMAT plug-in: has_rate_form) runs its own update, labelled "umat", against its self-reference
/// (self_reference); `notes` then gets the reference's description.
std::vector<WorkPrecisionRow> work_precision(const std::string& material_name, const Material& material,
                                             PointTest test, const WorkPrecisionOptions& options,
                                             const std::function<void(const WorkPrecisionRow&)>& on_row = {},
                                             std::vector<std::string>* notes = nullptr);

/// A model's own solution at fine increments as the reference of its work–precision: the runs at
/// F/4, F/2 and F increments per leg (F = 4 × `increments`), the observed order of convergence of q
/// from their differences, p = log2(‖q_{F/4} − q_{F/2}‖∞ / ‖q_{F/2} − q_F‖∞), and Richardson's
/// extrapolation u* = u_F + (u_F − u_{F/2}) / (2^p − 1) of q and p' (u_F itself where the differences
/// vanish), at the rows of `increments` per leg (Richardson 1911; Roache 1998, ch. 5).
struct SelfReference {
  PointCurve curve;  ///< at `increments` per leg; only q and p are extrapolated
  int finest = 0;    ///< F
  double observed_order = 0.0;  ///< NaN where the differences are at round-off (1e-12 of max |q|)
};
SelfReference self_reference(const Material& material, PointTest test, int increments);

/// CSV: a '#' comment line (units, definitions), then
/// material,path,integrator,increments,error_q,error_p,cpu_seconds,repeats.
void write_work_precision_csv(std::ostream& out, const std::vector<WorkPrecisionRow>& rows);

}  // namespace soilsph::verification
