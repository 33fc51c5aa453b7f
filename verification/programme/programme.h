#pragma once
/// @file
/// A laboratory programme at one material point: an initial state, then legs (paths/load_path.h),
/// each imposing per component a strain or a stress, drained or undrained. The built-in tests are
/// shorthands for one (programme_of); programme files give any other (programme_file.h). Both the
/// mixed-control driver and the CVODE reference run it.
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "constitutive/material.h"
#include "verification/paths/load_path.h"
#include "verification/point_test.h"

namespace soilsph::verification {

struct Programme {
  State initial;  ///< effective stress (tension-positive) and hardening state (MCC p_c)
  std::vector<Leg> legs;
  /// How a failure names leg l: "increment k of N of " + leg_names[l], or leg_names[l] alone for a
  /// strain-path row ("FILE:LINE").
  std::vector<std::string> leg_names;
  bool legs_are_rows = false;
  /// Driver sub-steps (verification/driver/path_substeps.h): 0 = off, one solve per increment;
  /// else the relative tolerance of their step-doubling control. The CVODE reference ignores it.
  double path_tolerance = 0.0;
};

/// The programme of a built-in test (validated; std::invalid_argument as run_point_test says).
Programme programme_of(const Material& material, const PointTest& test);

/// A run that stopped where the soil reached its strength under imposed stresses: what() names the
/// increment and the stress reached; `curve` holds the rows up to the last completed increment.
class StrengthReachedError : public std::runtime_error {
 public:
  StrengthReachedError(const std::string& message, PointCurve curve)
      : std::runtime_error(message), curve(std::move(curve)) {}
  PointCurve curve;
};

/// Runs `programme` with `integrator` (a scheme name or "cvode"). Throws std::invalid_argument for
/// an unknown integrator, std::runtime_error naming the increment when one cannot be solved or a
/// result has lost meaning (as run_point_test): StrengthReachedError, with the curve so far, when
/// the imposed stresses of a leg are beyond the soil's strength.
PointCurve run_programme(const Material& material, const Programme& programme, std::string_view integrator);

}  // namespace soilsph::verification
