// Each closed form against the driver's curves: the CVODE reference within 1e-5 and the paper's
// explicit scheme within a tolerance measured at the default 100 increments per leg (the measured
// maximum relative error is written next to each tolerance; errors are defined in curve_errors.h).
#include <catch2/catch.hpp>
#include <string>

#include "closed_form_fixtures.h"
#include "verification/closed_form/closed_form.h"
#include "verification/report/curve_errors.h"

using namespace soilsph;
using namespace soilsph::verification;
using Kind = Elasticity::Kind;

namespace {
/// Our bound on the CVODE reference against a closed form.
constexpr double kCvodeTolerance = 1e-5;

struct Case {
  std::string label;
  Material material;
  LoadPath path;
  double ocr;
  std::vector<double> targets;
  std::string closed_form;
  double explicit_tolerance;  ///< measured explicit error × ~1.5 (measured value in the comment)
};

CurveErrors errors_against_closed_form(const Case& c, std::string_view integrator) {
  PointTest test;
  test.path = c.path;
  test.ocr = c.ocr;
  test.strain_targets = c.targets;
  const PointCurve curve = run_point_test(c.material, test, integrator);
  std::vector<double> driven;
  for (const PointRecord& row : curve) driven.push_back(driven_strain(row, c.path));
  return curve_errors(curve, closed_form_curve(c.closed_form, c.material, test, driven), c.path);
}

std::vector<Case> cases() {
  const Material pd = test::table1_cam_clay(Kind::PressureDependent);
  const Material constant = test::table1_cam_clay(Kind::Constant);
  using enum LoadPath;
  return {
      // D-P (yield at ε_a ≈ 0.14 for E = 1 MPa, hence 0.3): explicit measured 1.8e-11 (Table 1),
      // 3.5e-15 (c = 5 kPa, ψ = 5°). (The printed eq 22, which drops f_n, kept the error made at the
      // yield crossing: 1.75e-2 and 3.4e-3.)
      {"D-P drained",
       test::table1_drucker_prager(),
       TriaxialDrained,
       1.0,
       {0.3},
       "dp-triaxial-drained",
       1e-10},
      {"D-P drained, c and psi",
       test::table1_drucker_prager(5e3, 5.0),
       TriaxialDrained,
       1.0,
       {0.3},
       "dp-triaxial-drained",
       1e-10},
      // D-P strain paths: CVODE measured ≤ 7e-14; explicit 1.3e-15 (undrained, Table 1), 1.4e-15
      // (undrained, c and ψ), 9e-15 (oedometer and isotropic load-unload: elastic throughout).
      {"D-P undrained",
       test::table1_drucker_prager(),
       TriaxialUndrained,
       1.0,
       {0.3},
       "dp-triaxial-undrained",
       1e-10},
      {"D-P undrained, c and psi",
       test::table1_drucker_prager(5e3, 5.0),
       TriaxialUndrained,
       1.0,
       {0.3},
       "dp-triaxial-undrained",
       1e-10},
      {"D-P oedometer",
       test::table1_drucker_prager(5e3, 5.0),
       Oedometer,
       1.0,
       {0.1, 0.05},
       "dp-oedometer",
       1e-10},
      {"D-P isotropic", test::table1_drucker_prager(), Isotropic, 1.0, {0.1, 0.05}, "dp-isotropic", 1e-10},
      // MCC undrained: measured 1.68e-2 (pd NC), 6.3e-3 (pd OCR 1.5), 8.8e-3 (constant NC), 2.4e-3
      // (constant OCR 1.5; its elastic range ends at ε_a = 0.087, so it runs to 0.3).
      {"MCC pd undrained NC", pd, TriaxialUndrained, 1.0, {0.1}, "mcc-triaxial-undrained", 2.5e-2},
      {"MCC pd undrained OCR 1.5", pd, TriaxialUndrained, 1.5, {0.1}, "mcc-triaxial-undrained", 1e-2},
      {"MCC constant undrained NC",
       constant,
       TriaxialUndrained,
       1.0,
       {0.3},
       "mcc-triaxial-undrained",
       1.4e-2},
      {"MCC constant undrained OCR 1.5",
       constant,
       TriaxialUndrained,
       1.5,
       {0.3},
       "mcc-triaxial-undrained",
       4e-3},
      // MCC drained: measured 4.8e-3 (pd NC), 6.0e-3 (pd OCR 1.5), 2.2e-3 (constant NC), 2.1e-3 (constant
      // OCR 1.5).
      {"MCC pd drained NC", pd, TriaxialDrained, 1.0, {0.1}, "mcc-triaxial-drained", 7.5e-3},
      {"MCC pd drained OCR 1.5", pd, TriaxialDrained, 1.5, {0.1}, "mcc-triaxial-drained", 9e-3},
      {"MCC constant drained NC", constant, TriaxialDrained, 1.0, {0.3}, "mcc-triaxial-drained", 3.5e-3},
      {"MCC constant drained OCR 1.5", constant, TriaxialDrained, 1.5, {0.3}, "mcc-triaxial-drained", 3.5e-3},
      // MCC isotropic load-unload-reload: measured 9.4e-2 and 9.5e-2 (pd, OCR 1 and 1.5), 2.4e-6
      // (constant NC), 1.3e-6 (constant OCR 1.5).
      {"MCC pd isotropic NC", pd, Isotropic, 1.0, {0.1, 0.05, 0.15}, "mcc-isotropic", 0.15},
      {"MCC pd isotropic OCR 1.5", pd, Isotropic, 1.5, {0.1, 0.05, 0.15}, "mcc-isotropic", 0.15},
      {"MCC constant isotropic NC", constant, Isotropic, 1.0, {0.1, 0.05, 0.15}, "mcc-isotropic", 4e-6},
      {"MCC constant isotropic OCR 1.5", constant, Isotropic, 1.5, {0.1, 0.05, 0.15}, "mcc-isotropic", 2e-6},
      // MCC oedometer load-unload-reload: measured 1.0e-2 (NC), 1.2e-2 (OCR 1.5).
      {"MCC pd oedometer NC", pd, Oedometer, 1.0, {0.1, 0.095, 0.15}, "mcc-oedometer", 2e-2},
      {"MCC pd oedometer OCR 1.5", pd, Oedometer, 1.5, {0.1, 0.095, 0.15}, "mcc-oedometer", 2e-2},
  };
}
}  // namespace

TEST_CASE("closed forms against the CVODE reference (relative error <= 1e-5)", "[closed-form][cvode]") {
  for (const Case& c : cases()) {
    DYNAMIC_SECTION(c.label) {
      const CurveErrors e = errors_against_closed_form(c, kReferenceIntegrator);
      INFO("q " << e.q << ", p' " << e.p << ", eps_v " << e.eps_v);
      CHECK(e.max() <= kCvodeTolerance);
    }
  }
}

TEST_CASE("closed forms against the explicit scheme at 100 increments per leg", "[closed-form][explicit]") {
  for (const Case& c : cases()) {
    DYNAMIC_SECTION(c.label) {
      const CurveErrors e = errors_against_closed_form(c, "explicit");
      INFO("q " << e.q << ", p' " << e.p << ", eps_v " << e.eps_v);
      CHECK(e.max() <= c.explicit_tolerance);
    }
  }
}

TEST_CASE("a closed form refuses a model or path it does not describe", "[closed-form]") {
  PointTest test;
  const std::vector<double> driven = {0.0, 0.01};
  CHECK_THROWS(closed_form_curve("mcc-triaxial-drained", test::table1_drucker_prager(), test, driven));
  test.path = LoadPath::Oedometer;
  CHECK_THROWS(closed_form_curve("mcc-triaxial-drained", test::table1_cam_clay(Kind::PressureDependent), test,
                                 driven));
  CHECK_THROWS(closed_form_curve("mcc-oedometer", test::table1_cam_clay(Kind::Constant), test, driven));
  CHECK_THROWS(closed_form_curve("no-such-form", test::table1_drucker_prager(), test, driven));
}
