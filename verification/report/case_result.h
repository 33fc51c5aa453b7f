#pragma once
/// @file
/// Running one verification case: the CVODE reference, the closed form at the reference's strains, and
/// every listed integrator, each compared with both. An integrator passes when its errors against the
/// closed form (if the case has one) and against CVODE (for integrators other than CVODE itself) are
/// within its tolerance; a run that throws fails with its message.
#include <optional>
#include <string>
#include <vector>

#include "verification/report/curve_errors.h"
#include "verification/report/verification_case.h"

namespace soilsph::verification {

struct IntegratorRun {
  std::string integrator;
  double tolerance = 0.0;
  PointCurve curve;
  std::optional<CurveErrors> vs_closed_form;
  std::optional<CurveErrors> vs_reference;  ///< against CVODE; empty for CVODE itself
  std::string failure;                      ///< why the run failed to produce a curve, if it did
  bool passed = false;
  /// False for CVODE in a case without a closed form: the yardstick met nothing, so it neither
  /// passes nor fails (the report says "no closed form").
  bool compared = true;
};

struct CaseResult {
  const VerificationCase* spec = nullptr;
  PointCurve reference;                     ///< the CVODE curve (empty if it failed)
  std::string reference_failure;            ///< CVODE's error message, if any
  std::vector<ReferencePoint> closed_form;  ///< at the reference's driven strains (empty if none)
  std::vector<IntegratorRun> runs;
  bool passed() const;
};

CaseResult run_case(const VerificationCase& spec);

}  // namespace soilsph::verification
