#pragma once
/// @file
/// Mixed control at one material point, in the spirit of MTest: each Voigt component has either
/// its strain or its stress imposed (paths/load_path.h). Each increment solves for the free strain
/// components by Newton's method on the imposed stresses,
///   r(Δε_f) = σ_f(σ_n, Δε_i, Δε_f) − σ_f*,   Δε_f ← Δε_f − T_ff⁻¹ r,
/// and on an undrained leg also for the pore pressure u, with σ_f* total stresses and the volume
/// held (mixed_control_algebra.h: r = σ'_f − u m_f − σ_f*, bordered by m · Δε = 0),
/// with T the algorithmic tangent of one update (constitutive/tangent.h: the model's consistent
/// tangent, else central differences), until ‖r‖∞ ≤ tolerance · max(‖σ_f*‖∞, 10⁻³ ‖σ‖∞) (relative to
/// the imposed stresses; the floor covers imposed zero stresses). The first guess is the elastic
/// solution at σ_n. Templated on the model: called once per run from a std::visit.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "constitutive/models/umat.h"
#include "constitutive/tangent.h"
#include "verification/driver/mixed_control_algebra.h"
#include "verification/driver/path_substeps.h"
#include "verification/driver/point_history.h"
#include "verification/driver/strength_limit.h"

namespace soilsph::verification {

struct MixedControlOptions {
  double tolerance = 1e-10;  ///< relative residual of the imposed stresses
  int max_iterations = 50;
  int max_splits = 8;  ///< halvings of an increment whose Newton fails (up to 2^max_splits parts)
  /// Driver sub-steps (path_substeps.h): 0 (the default) solves each increment of a leg with stress-
  /// imposed components once, meeting the imposed stresses at its end only; > 0 splits it into
  /// sub-steps until the step-doubling estimate of the increment's error is ≤ this (relative). Strain-controlled legs are never split
  /// (their path is exact).
  double path_tolerance = 0.0;
  int max_path_substeps = 4096;  ///< per increment
};

namespace detail {
/// The update for a trial strain increment and its residual on the imposed stresses (‖·‖∞, Pa).
/// An update that fails (a scheme's std::runtime_error, e.g. no convergence for this trial) gives
/// an infinite residual, so that damped Newton backs off from it.
struct Trial {
  State state;
  double pore_pressure = 0.0;
  Vec6 residual = Vec6::Zero();
  double norm = 0.0;
};

template <class Model>
Trial evaluate(const Model& model, const State& state, const Partition& part, const Vec6& target,
               const Vec6& strain_increment, double pore_pressure, std::string& update_error) {
  Trial t;
  t.pore_pressure = pore_pressure;
  try {
    t.state = model.update(state, strain_from_voigt(strain_increment), Mat3::Zero());
  } catch (const UmatError&) {
    throw;  // a plug-in's failure is its own, not the trial's: said once, not retried as a bad guess
  } catch (const std::runtime_error& e) {
    t.norm = std::numeric_limits<double>::infinity();
    update_error = e.what();
    return t;
  }
  const Vec6 sigma = stress_to_voigt(t.state.stress);
  for (int a = 0; a < part.n_free; ++a) {
    const int k = part.free[a];
    t.residual(k) = sigma(k) - pore_pressure * voigt_identity(k) - target(k);
    t.norm = std::max(t.norm, std::abs(t.residual(part.free[a])));
  }
  // std::max drops a NaN, so a non-finite trial (e.g. from a singular tangent solve) must be
  // caught here, or it would pass as converged.
  if (!sigma.allFinite() || !std::isfinite(t.state.pc)) t.norm = std::numeric_limits<double>::infinity();
  return t;
}

/// Newton from the elastic guess; with `damped`, each step is halved until the residual decreases.
/// `pore_pressure` is u at the start of the increment (0 when drained).
template <class Model>
std::optional<Trial> solve_increment(const Model& model, const State& state, double pore_pressure,
                                     const Partition& part, const Leg& leg, const Vec6& target,
                                     Vec6& strain_increment, const MixedControlOptions& options, bool damped,
                                     std::string& update_error) {
  Vec6 total_n = stress_to_voigt(state.stress);
  total_n.head<3>().array() -= pore_pressure;
  strain_increment = leg.increment;
  const double du = solve_free(voigt_stiffness(model.elasticity().at(mean_pressure(state.stress))), part,
                               target - total_n, strain_increment);
  Trial trial = evaluate(model, state, part, target, strain_increment, pore_pressure + du, update_error);
  double imposed_scale = 0.0;
  for (int a = 0; a < part.n_free; ++a)
    imposed_scale = std::max(imposed_scale, std::abs(target(part.free[a])));
  constexpr int kMaxHalvings = 30;
  for (int iteration = 0;; ++iteration) {
    const double scale = std::max(imposed_scale, 1e-3 * trial.state.stress.cwiseAbs().maxCoeff());
    if (trial.norm <= options.tolerance * scale) return trial;
    if (iteration == options.max_iterations || !std::isfinite(trial.norm)) return std::nullopt;
    // Newton: T_ff δ_f = −r_f with the strain-imposed entries held (δ_i = 0).
    const Mat6 tangent = algorithmic_tangent(model, state, strain_from_voigt(strain_increment));
    Vec6 correction = Vec6::Zero();
    const double du_correction = solve_free(tangent, part, -trial.residual, correction);
    double step = 1.0;
    for (int halving = 0;; ++halving, step *= 0.5) {
      Trial next = evaluate(model, state, part, target, strain_increment + step * correction,
                            trial.pore_pressure + step * du_correction, update_error);
      if (!damped || next.norm < trial.norm || halving == kMaxHalvings) {
        strain_increment += step * correction;
        trial = std::move(next);
        break;
      }
    }
  }
}
}  // namespace detail

/// One increment of `leg` from `state` to the imposed stresses `target` (Voigt; only the
/// stress-imposed entries are used; total stresses on an undrained leg): returns the new state and
/// sets `strain_increment` (Voigt, engineering shears) to the imposed and solved components, and
/// `pore_pressure` from u at the start to u at the end. Plain Newton first; if it fails,
/// Newton damped by backtracking, because a discrete update need not be smooth (with large
/// increments the explicit scheme's residual has kinks and several branches). If both fail, the
/// increment is done as two halves, recursively up to `options.max_splits` times (a coarse
/// softening step can lead Newton from the elastic guess to a stress-free state, where the tangent
/// vanishes). Throws std::runtime_error if even the smallest pieces fail.
template <class Model>
State mixed_control_increment(const Model& model, const State& state, const Leg& leg, const Vec6& target,
                              Vec6& strain_increment, double& pore_pressure,
                              const MixedControlOptions& options = {}, int splits = 0) {
  const Partition part(leg);
  if (part.n_free == 0) {  // strain control: one update, whose errors propagate as they are
    strain_increment = leg.increment;
    return model.update(state, strain_from_voigt(strain_increment), Mat3::Zero());
  }
  std::string update_error;
  for (bool damped : {false, true}) {
    if (auto solved = detail::solve_increment(model, state, pore_pressure, part, leg, target,
                                              strain_increment, options, damped, update_error)) {
      pore_pressure = solved->pore_pressure;
      return solved->state;
    }
  }
  if (splits < options.max_splits) {
    Leg half = leg;
    half.increment = 0.5 * leg.increment;
    const Vec6 middle_target = target - half.increment;  // used on the stress-imposed entries only
    Vec6 first, second;
    double u = pore_pressure;
    const State middle =
        mixed_control_increment(model, state, half, middle_target, first, u, options, splits + 1);
    const State end = mixed_control_increment(model, middle, half, target, second, u, options, splits + 1);
    pore_pressure = u;
    strain_increment = first + second;
    return end;
  }
  throw std::runtime_error("mixed control: Newton did not converge on the imposed stresses in " +
                           std::to_string(options.max_iterations) + " iterations, plain or damped, in 2^" +
                           std::to_string(options.max_splits) +
                           " parts of the increment (more increments may help)" +
                           (update_error.empty() ? "" : "; the update failed: " + update_error));
}

/// Runs every leg from `initial`: one sample per increment, the initial state first; a failed
/// increment throws IncrementError, which holds the samples completed when the failure is the soil's
/// strength (strength_limit.h). With options.path_tolerance > 0 an increment of a leg with
/// stress-imposed components is done in error-controlled sub-steps (path_substeps.h), still one
/// sample per increment. The imposed
/// stresses are accumulated as targets (not added to the last solved stress), so the residuals
/// left by each Newton solve do not drift. A drained leg starts with u = 0.
template <class Model>
PointHistory drive_mixed_control(const Model& model, const State& initial, std::span<const Leg> legs,
                                 const MixedControlOptions& options = {}) {
  PointHistory history{{Mat3::Zero(), initial}};
  const auto solve = [&](const State& from, const Leg& sub, const Vec6& sub_target, Vec6& d, double& u) {
    return mixed_control_increment(model, from, sub, sub_target, d, u, options);
  };
  // The strength's bisection (strength_limit.h) tries parts of an increment that mostly fail: with
  // two splits at most a failing trial costs 4 Newton solves, not 2^max_splits.
  MixedControlOptions probe_options = options;
  probe_options.max_splits = std::min(options.max_splits, 2);
  const auto probe = [&](const State& from, const Leg& sub, const Vec6& sub_target, Vec6& d, double& u) {
    return mixed_control_increment(model, from, sub, sub_target, d, u, probe_options);
  };
  Vec6 target = stress_to_voigt(initial.stress);
  std::array<bool, 6> held{};
  bool was_undrained = false;
  for (std::size_t l = 0; l < legs.size(); ++l) {
    const Leg leg = resolve_leg(legs[l], history.back());
    // Opening the drainage dissipates the excess pore pressure: held total stresses become the
    // effective stresses reached.
    if (leg.undrained != was_undrained) held = {};
    was_undrained = leg.undrained;
    const bool path_control = options.path_tolerance > 0.0 && Partition(leg).n_free > 0;
    PathSubsteps substeps;  // each leg starts from one sub-step pair (1, 2)
    const Mat3 leg_start_strain = history.back().strain;
    for (int k = 0; k < leg.increments; ++k) {
      const PointSample& last = history.back();
      double u = leg.undrained ? last.pore_pressure : 0.0;
      // A component that becomes stress-imposed starts from the (total) stress it has reached.
      Vec6 current = stress_to_voigt(last.state.stress);
      current.head<3>().array() -= u;
      for (int c = 0; c < 6; ++c) {
        if (!leg.stress_imposed[c]) continue;
        target(c) = (held[c] ? target(c) : current(c)) + leg.increment(c);
      }
      held = leg.stress_imposed;
      Vec6 strain_increment;
      try {
        State next =
            path_control
                ? path_controlled_increment(
                      solve, last.state, strain_to_voigt(last.strain - leg_start_strain), leg, target,
                      options.path_tolerance, options.max_path_substeps, substeps, strain_increment, u)
                : mixed_control_increment(model, last.state, leg, target, strain_increment, u, options);
        history.push_back({last.strain + strain_from_voigt(strain_increment), next, u});
      } catch (const std::runtime_error& e) {
        // An increment with imposed stresses that cannot be solved: the soil's strength, if the
        // furthest state it reaches lies on the yield surface (strength_limit.h).
        if (Partition(leg).n_free > 0)
          if (const auto reached = strength_reached(model, probe, last.state, u, leg, target))
            throw IncrementError(strength_message(*reached), l, k, std::move(history));
        throw IncrementError(e.what(), l, k);
      }
    }
  }
  return history;
}

}  // namespace soilsph::verification
