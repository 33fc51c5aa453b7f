#pragma once
/// @file
/// What a failed increment of a leg with imposed stresses means: whether the soil has reached its
/// strength there.
///
/// Why: under stress control the strain response of a hardening soil grows without bound towards
/// the critical state, and a perfectly plastic one (Drucker–Prager, Mohr–Coulomb) carries no stress
/// beyond its failure surface at all. An increment whose imposed stresses lie beyond the strength
/// has no solution: Newton fails, and so does every split of the increment. More increments cannot
/// help; the user has to be told that the soil has failed, where, and be given the curve up to
/// there.
///
/// What: the largest fraction α of the failed increment the soil carries is found by bisection
/// (each trial one mixed-control solve of the increment scaled by α, from the increment's start).
/// When the state reached at that fraction lies on the yield surface (normalized yield ≥ −10⁻³),
/// the imposed stresses are at or beyond the strength there: the increment is reported with that
/// state. A state off the surface means Newton failed for another reason, and the failure is
/// reported as it is.
#include <optional>
#include <stdexcept>
#include <string>

#include "constitutive/model_concept.h"
#include "constitutive/parameters.h"
#include "constitutive/state.h"
#include "constitutive/voigt.h"
#include "verification/paths/load_path.h"

namespace soilsph::verification {

/// The furthest state of a failed increment, on the yield surface.
struct StrengthReached {
  double fraction = 0.0;  ///< of the increment carried, in [0, 1)
  State state;
  double pore_pressure = 0.0;
};

/// Bisections of the carried fraction: 2⁻¹² of an increment is finer than any curve is read.
inline constexpr int kStrengthBisections = 12;
/// A state whose normalized yield value is at least this lies on the yield surface.
inline constexpr double kOnYieldSurface = -1e-3;

/// The furthest state of `leg`'s increment from `start` (pore pressure `u`) towards `target` (the
/// imposed stresses at its end) that `solve(start, sub_leg, sub_target, strain_increment, u)`
/// reaches, if it lies on the yield surface of `model`; std::nullopt otherwise (and for a model
/// without one).
template <class Model, class Solve>
std::optional<StrengthReached> strength_reached(const Model& model, const Solve& solve, const State& start,
                                                double u, const Leg& leg, const Vec6& target) {
  if constexpr (!PlasticModel<Model>) {
    return std::nullopt;
  } else {
    const Vec6 start_target = target - leg.increment;  // used on the stress-imposed entries only
    StrengthReached reached{0.0, start, u};
    double failed = 1.0;
    for (int i = 0; i < kStrengthBisections; ++i) {
      const double fraction = 0.5 * (reached.fraction + failed);
      Leg part = leg;
      part.increment = fraction * leg.increment;
      Vec6 strain_increment;
      double trial_u = u;
      try {
        const State state =
            solve(start, part, Vec6(start_target + part.increment), strain_increment, trial_u);
        reached = {fraction, state, trial_u};
      } catch (const std::runtime_error&) {
        failed = fraction;
      }
    }
    if (model.normalized_yield(reached.state.stress, reached.state.pc) < kOnYieldSurface) return std::nullopt;
    return reached;
  }
}

/// The message for a leg that reached the soil's strength: how much of the increment the soil
/// carries and the stress there (compression-positive p', q and total normal stresses, Pa).
inline std::string strength_message(const StrengthReached& reached) {
  const Mat3& sigma = reached.state.stress;
  const auto total = [&](int k) { return format_number(-(sigma(k, k) - reached.pore_pressure)); };
  return "the imposed stress is at or beyond the soil's strength: the soil carries " +
         format_number(100.0 * reached.fraction) +
         " % of this increment and no more, reaching p' = " + format_number(mean_pressure(sigma)) +
         " Pa, q = " + format_number(deviatoric_stress(sigma)) + " Pa (sigma_xx = " + total(0) +
         ", sigma_yy = " + total(1) + ", sigma_zz = " + total(2) +
         " Pa, compression-positive) on its yield surface; more increments cannot carry it further (impose a "
         "strain to follow the soil past its strength); the curve is written up to the last completed "
         "increment";
}

}  // namespace soilsph::verification
