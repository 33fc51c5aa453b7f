#pragma once
/// @file
/// The numerical-stability stress test: a reproducible random strain walk through one model with
/// one integrator, checking after every increment that nothing is NaN/Inf, the stress is on or
/// inside the yield surface within a tolerance, MCC p' ≥ 0 (to a tolerance of the increment's own
/// stress scale) and p_c > 0, and Δλ ≥ 0.
/// The walk is built from segments of 1–50 increments, each with one character: any direction,
/// extension (through the D-P apex, MCC p' → 0), compression, pure shear (towards the critical
/// state line), or the reverse of the previous segment (unloading). Increment sizes are log-uniform
/// in [1e-6, max_increment]; each carries a random spin of the same order. The walk restarts from
/// a fresh random state every `restart_every` increments, after a failure, and when the state leaves
/// the range where it means anything (|p| > 1 GPa, or MCC p_c outside 1e-9 Pa–1 GPa). A quarter of
/// the MCC starts are free-surface "dust" (p from 1e-9 to 1 Pa). See docs/method/integrators.md.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "constitutive/material.h"

namespace soilsph {

/// The admissible range lo ≤ STATEV(index) ≤ hi of one UMAT state variable (index from 1).
struct StateVariableRange {
  int index = 1;
  double lo = 0.0, hi = 0.0;
};

struct StressTestOptions {
  long increments = 100000;
  std::uint64_t seed = 1;
  double max_increment = 5e-2;    ///< largest strain-increment norm
  double yield_tolerance = 1e-8;  ///< accepted normalized_yield() after an update
  long restart_every = 2000;      ///< increments between fresh random starting states
  // A UMAT plug-in (run_umat_stress_test), whose yield surface soilsph does not know:
  std::vector<StateVariableRange> state_ranges;  ///< every update's STATEV must stay in these
  long tangent_every = 10;                       ///< DDSDDE against central differences every N increments
  double tangent_tolerance = 1e-3;  ///< accepted ‖DDSDDE − D_fd‖ / ‖D_fd‖ (Frobenius norms)
};

struct StressTestResult {
  long increments = 0;
  long plastic = 0;                   ///< increments with Δλ > 0
  long extension = 0;                 ///< increments with a positive (tensile) volume change
  long unloading = 0;                 ///< increments of a reversed segment
  long at_apex = 0;                   ///< D-P: increments ending at the apex (s = 0 and f = 0)
  long near_zero_pressure = 0;        ///< MCC: increments ending with p' < 0.01 p_c
  long near_critical_state = 0;       ///< MCC: plastic increments ending with |q/(M p') − 1| < 0.05
  long failures = 0;                  ///< IntegrationError thrown (counted, then the walk restarts)
  long violations = 0;                ///< increments that broke a check
  double max_yield = -1e300;          ///< largest normalized yield value seen
  double min_pressure_ratio = 1e300;  ///< MCC: smallest p'/p_c seen
  std::string first_problem;          ///< description of the first failure or violation
  State problem_start;                ///< the state before that increment (to reproduce it)
  Mat3 problem_strain = Mat3::Zero(), problem_spin = Mat3::Zero();  ///< and the increment
  double seconds = 0.0;                                             ///< wall time of the walk
  long tangent_checks = 0;           ///< UMAT: increments whose DDSDDE was compared with central differences
  long tangent_mismatches = 0;       ///< UMAT: of those, beyond tangent_tolerance (counted as violations too)
  double worst_tangent_error = 0.0;  ///< UMAT: the largest relative difference seen
};

/// Runs the walk for `material` with its integrator replaced by `integrator` (not for linear elastic).
StressTestResult run_stress_test(const Material& material, Integrator integrator,
                                 const StressTestOptions& options);

/// Runs the walk for a UMAT plug-in with its own update. Its yield surface is the plug-in's own, so
/// the checks are those that hold for any model: a finite STRESS and STATEV (a UmatError counts as a
/// failure), every STATEV in `options.state_ranges`, and every `tangent_every`-th increment the
/// returned DDSDDE against central differences of the update (constitutive/tangent.h).
StressTestResult run_umat_stress_test(const UmatModel& umat, const StressTestOptions& options);

/// One material of the stress test: its description, a short label (benchmark names) and the model.
struct StressTestMaterial {
  std::string name;
  std::string label;
  Material material;
};

/// A stress scale (Pa) of one increment that its result cannot inflate: the start's p_c and p and an
/// elastic bound on the trial's change (the tangent moduli at the start). The stress test holds MCC's
/// p' ≥ 0 and f to tolerances of it.
template <class Model>
double increment_scale(const Model& model, const State& start, const Mat3& d_eps) {
  const double p = mean_pressure(start.stress);
  const Moduli D = model.elasticity().at(p);
  return std::max({start.pc, std::abs(p), 3.0 * (D.K + 2.0 * D.G) * d_eps.norm()});
}

/// The materials the stress test covers: Table 1 D-P (c = 0, ψ = 0), a cohesive dilatant D-P
/// (c = 5 kPa, ψ = 10°), Table 1 MCC with pressure-dependent and with constant elasticity, and
/// Mohr–Coulomb with the Table 1 soil's φ (c = 5 kPa, ψ = 10°; and with a tension cut-off of 2 kPa).
std::vector<StressTestMaterial> stress_test_materials();

}  // namespace soilsph
