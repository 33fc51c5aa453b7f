#pragma once
// The stiff clay's triaxial paths (to ε_a = 0.1 from p0 = 200 kPa, one leg) and their error
// against the CVODE reference, shared by the MCC accuracy tests.
#include <catch2/catch.hpp>

#include "verification/point_test.h"
#include "verification/report/curve_errors.h"

namespace soilsph::test {

inline verification::PointTest triaxial(verification::LoadPath path, double ocr, int increments,
                                        double path_tolerance = 0.0) {
  verification::PointTest t;
  t.path = path;
  t.p_initial = 200e3;
  t.ocr = ocr;
  t.strain_targets = {0.1};
  t.increments = increments;
  t.path_tolerance = path_tolerance;
  return t;
}

/// Largest relative error (curve_errors) of `integrator` against CVODE; one row per requested
/// increment whatever the sub-steps.
inline double error_vs_cvode(const Material& material, const verification::PointTest& test, const char* integrator) {
  using namespace verification;
  const PointCurve reference = run_point_test(material, test, kReferenceIntegrator);
  const PointCurve curve = run_point_test(material, test, integrator);
  REQUIRE(curve.size() == static_cast<std::size_t>(test.increments) + 1);
  return curve_errors(curve, as_reference(reference), test.path).max();
}

}  // namespace soilsph::test
