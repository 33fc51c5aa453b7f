#pragma once
/// @file
/// The model hooks (model_concept.h) that every model without a hardening variable shares, written
/// once: p_c stays 0 (an OCR has nothing to set), and, for a perfectly plastic model, no hardening
/// term, no hardening rate for the CVODE reference, and the apex as its stress-test mark. Models
/// inherit them as plain members (no virtual functions), and the keys the frictional models share.
#include <limits>

#include "constitutive/material_limits.h"
#include "constitutive/parameters.h"
#include "constitutive/state.h"

namespace soilsph {

/// No hardening variable: p_c stays 0.
struct NoHardeningVariable {
  static constexpr bool kHasPreconsolidation = false;
  double initial_preconsolidation(const Mat3&, double /*ocr*/, double /*floor*/ = 0.0) const { return 0.0; }
};

/// Perfect plasticity: yield surface fixed in stress space.
struct PerfectPlasticity : NoHardeningVariable {
  /// No hardening term in the consistency condition.
  double hardening_modulus(const Mat3&, double) const { return 0.0; }
  double harden(double pc, const Mat3& /*d_plastic_strain*/) const { return pc; }
  /// ṗ_c of the rate equations (CVODE reference): none.
  double hardening_rate(const Mat3&, double, double /*lambda_dot*/, const Mat3& /*n_g*/) const { return 0.0; }
  /// The stress test's mark: a plastic state at the apex (s = 0 exactly).
  StateMarks marks(const State& s) const {
    return {s.plastic_multiplier > 0.0 && second_deviatoric_invariant(s.stress) == 0.0, false, false};
  }
};

/// The parameters Drucker–Prager and Mohr–Coulomb share (their Params add the rest).
struct FrictionalParams {
  double density = 0.0;          ///< kg/m³ (required)
  double young_modulus = 0.0;    ///< Pa (required)
  double poisson_ratio = 0.0;    ///< − (required)
  double friction_angle = 0.0;   ///< φ, degrees (required)
  double cohesion = 0.0;         ///< c, Pa
  double dilatancy_angle = 0.0;  ///< ψ, degrees, 0 ≤ ψ ≤ φ
  /// Plastic volumetric strain at which dilation stops (ψ → 0; models/dilatancy_cutoff.h), +∞: none.
  double dilatancy_cutoff = std::numeric_limits<double>::infinity();
  /// τ, s: Duvaut–Lions relaxation time in the SPH solver (constitutive/viscoplastic_relaxation.h); 0:
  /// rate-independent.
  double viscoplastic_relaxation_time = 0.0;
};

/// Their keys, ranges and defaults, for Params::fields: density, E, ν, φ, c (default 0), ψ (default
/// 0, at most φ), the dilatancy cut-off (default none; a plastic volumetric strain up to 1, e^1 times
/// the volume, far beyond any soil's), the viscoplastic relaxation time (default 0).
template <class Io>
void frictional_fields(const Io& io, FrictionalParams& p) {
  io.number("density", p.density, Range::positive(), "kg/m^3");
  io.number("young_modulus", p.young_modulus, limits::young_modulus_range(), "Pa");
  io.number("poisson_ratio", p.poisson_ratio, Range::open(-1.0, 0.5));
  io.number("friction_angle", p.friction_angle, Range::open(0.0, 90.0), "degrees");
  io.number_or("cohesion", p.cohesion, Range::closed(0.0, limits::kMaxStress), "Pa");
  io.number_or("dilatancy_angle", p.dilatancy_angle, Range::closed(0.0, p.friction_angle), "degrees");
  io.number_if_given("dilatancy_cutoff", p.dilatancy_cutoff, Range::open_closed(0.0, 1.0));
  io.number_or("viscoplastic_relaxation_time", p.viscoplastic_relaxation_time,
               limits::relaxation_time_range(), "s", Listed::WhenSet);
}

}  // namespace soilsph
