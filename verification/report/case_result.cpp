#include "verification/report/case_result.h"

#include <algorithm>

#include "verification/closed_form/closed_form.h"

namespace soilsph::verification {

bool CaseResult::passed() const {
  return std::all_of(runs.begin(), runs.end(), [](const IntegratorRun& r) { return r.passed; });
}

CaseResult run_case(const VerificationCase& spec) {
  CaseResult result;
  result.spec = &spec;
  const bool umat = std::holds_alternative<UmatModel>(spec.material);
  try {
    if (!umat) result.reference = run_point_test(spec.material, spec.test, kReferenceIntegrator);
  } catch (const std::exception& e) {
    result.reference_failure = e.what();
  }
  for (const auto& [integrator, tolerance] : spec.tolerances) {
    IntegratorRun run;
    run.integrator = integrator;
    run.tolerance = tolerance;
    try {
      run.curve =
          integrator == kReferenceIntegrator ? result.reference
          : umat ? run_point_test(spec.material, spec.test, "implicit")  // its own update: the name is unused
                 : run_point_test(spec.material, spec.test, integrator);
      if (run.curve.empty()) throw std::runtime_error(result.reference_failure);
      if (spec.closed_form != "none") {
        std::vector<double> driven;
        for (const PointRecord& row : run.curve) driven.push_back(driven_strain(row, spec.test.path));
        const auto closed = closed_form_curve(spec.closed_form, spec.closed_form_source(), spec.test, driven);
        run.vs_closed_form = curve_errors(run.curve, closed, spec.test.path);
        if (result.closed_form.empty()) result.closed_form = closed;
      }
      if (integrator != kReferenceIntegrator && !result.reference.empty())
        run.vs_reference = curve_errors(run.curve, as_reference(result.reference), spec.test.path);
      if (!run.vs_closed_form && !run.vs_reference) {
        // CVODE without a closed form is the yardstick itself; anything else needs something to meet.
        run.passed = integrator == kReferenceIntegrator;
        run.compared = false;
        if (!run.passed) run.failure = "no reference to compare with (CVODE failed and no closed form)";
        result.runs.push_back(std::move(run));
        continue;
      }
      const double worst = std::max(run.vs_closed_form ? run.vs_closed_form->max() : 0.0,
                                    run.vs_reference ? run.vs_reference->max() : 0.0);
      run.passed = worst <= tolerance;
    } catch (const std::exception& e) {
      run.failure = e.what();
    }
    result.runs.push_back(std::move(run));
  }
  return result;
}

}  // namespace soilsph::verification
