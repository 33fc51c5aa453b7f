// MCC `implicit` against the CVODE reference on drained and undrained triaxial paths to ε_a = 0.1,
// for both elasticities (constant E of Table 1; K = (1+e0)p/κ) and OCR 1 and 1.5 from p0 = 200 kPa:
// the target of issue #11 item 4 is a relative error ≤ 1e-3 (verification/report/curve_errors) with
// 20 increments in all eight cases.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "tests/common/table1_materials.h"
#include "verification/point_test.h"
#include "verification/report/curve_errors.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
PointTest triaxial(LoadPath path, double ocr, int increments) {
  PointTest t;
  t.path = path;
  t.p_initial = 200e3;
  t.ocr = ocr;
  t.strain_targets = {0.1};
  t.increments = increments;
  return t;
}

ModifiedCamClay table1(Elasticity::Kind kind, double implicit_tolerance) {
  auto params = test::table1_cam_clay_params(kind);
  params.implicit_tolerance = implicit_tolerance;
  return ModifiedCamClay(params);
}

double error_vs_cvode(const Material& material, const PointTest& test, const char* integrator) {
  const PointCurve reference = run_point_test(material, test, kReferenceIntegrator);
  return curve_errors(run_point_test(material, test, integrator), as_reference(reference), test.path).max();
}
}  // namespace

TEST_CASE("MCC implicit with implicit_tolerance = 1e-3: undrained triaxial within 1e-3 of CVODE in 20 increments",
          "[integrators][cvode]") {
  // The target of issue #11 item 4. The expectation is CVODE's curve; the tolerance is the target.
  // Without control the pressure-dependent clay (K = 17.7 MPa at 200 kPa, 21x the Table 1 constant
  // E) errs by 8.4e-3 (OCR 1) and 2.5e-3 (OCR 1.5): it reaches the critical state within ε_a ≈ 0.02,
  // four increments, which the midpoint rule cannot resolve (a constant E of the same stiffness errs
  // by 1.9e-2: stiffness, not the elastic law, sets the error).
  for (auto kind : {Elasticity::Kind::Constant, Elasticity::Kind::PressureDependent})
    for (double ocr : {1.0, 1.5}) {
      INFO((kind == Elasticity::Kind::Constant ? "constant" : "pressure-dependent") << ", OCR " << ocr);
      const double error = error_vs_cvode(table1(kind, 1e-3), triaxial(LoadPath::TriaxialUndrained, ocr, 20), "implicit");
      CHECK(error <= 1e-3);
    }
}

TEST_CASE("MCC implicit with implicit_tolerance = 1e-3, drained triaxial: constant E within 1e-3 of CVODE in 20 "
          "increments; K ∝ p at the driver's limit",
          "[integrators][cvode]") {
  for (double ocr : {1.0, 1.5}) {
    INFO("OCR " << ocr);
    CHECK(error_vs_cvode(table1(Elasticity::Kind::Constant, 1e-3), triaxial(LoadPath::TriaxialDrained, ocr, 20),
                         "implicit") <= 1e-3);
    // The drained driver imposes a straight strain path inside each increment and holds σ_r only at
    // its end; CVODE holds σ_r throughout. For the stiff clay that path difference is 2.5e-3 (OCR 1)
    // and 1.6e-3 (OCR 1.5) at 20 increments, whatever the integrator: substep at tolerance 1e-8 errs
    // by the same. The target (1e-3) is not met here; the controlled implicit is within 10 % of the
    // near-exact integration of the driver's path.
    auto accurate = test::table1_cam_clay_params(Elasticity::Kind::PressureDependent);
    accurate.substep_tolerance = 1e-8;
    const PointTest t = triaxial(LoadPath::TriaxialDrained, ocr, 20);
    const double driver_limit = error_vs_cvode(ModifiedCamClay(accurate), t, "substep");
    const double controlled = error_vs_cvode(table1(Elasticity::Kind::PressureDependent, 1e-3), t, "implicit");
    INFO("substep 1e-8: " << driver_limit << ", implicit 1e-3: " << controlled);
    CHECK(driver_limit > 1e-3);
    CHECK(std::abs(controlled - driver_limit) <= 0.1 * driver_limit);
  }
}

TEST_CASE("MCC controlled implicit: the tangent of a split increment is the derivative of the update",
          "[integrators]") {
  // An undrained NC increment of 5e-3 from the tip: the stiff clay needs several sub-increments.
  const ModifiedCamClay mcc = table1(Elasticity::Kind::PressureDependent, 1e-3);
  State start;
  start.stress = isotropic_stress(200e3);
  start.pc = 200e3;
  Mat3 d = Mat3::Zero();
  d(0, 0) = -5e-3, d(1, 1) = d(2, 2) = 2.5e-3;
  const Mat6 tangent = mcc.consistent_tangent(start, d);
  const Vec6 base = strain_to_voigt(d);
  const double h = 1e-9;
  for (int k = 0; k < 6; ++k) {
    Vec6 plus = base, minus = base;
    plus(k) += h, minus(k) -= h;
    const Vec6 column = (stress_to_voigt(mcc.update(start, strain_from_voigt(plus), Mat3::Zero()).stress) -
                         stress_to_voigt(mcc.update(start, strain_from_voigt(minus), Mat3::Zero()).stress)) /
                        (2.0 * h);
    INFO("column " << k << ": " << column.transpose() << " vs " << tangent.col(k).transpose());
    CHECK((column - tangent.col(k)).norm() <= 1e-5 * tangent.norm());
  }
}

TEST_CASE("MCC implicit error matrix (printed, not checked)", "[.matrix]") {
  for (double tolerance : {0.0, 1e-2, 3e-3, 1e-3, 1e-4})
  for (auto kind : {Elasticity::Kind::Constant, Elasticity::Kind::PressureDependent}) {
    auto params = test::table1_cam_clay_params(kind);
    params.implicit_tolerance = tolerance;
    const Material mcc = ModifiedCamClay(params);
    for (LoadPath path : {LoadPath::TriaxialDrained, LoadPath::TriaxialUndrained})
      for (double ocr : {1.0, 1.5}) {
        std::printf("tol %.0e %-18s %-19s OCR %.1f:", tolerance, kind == Elasticity::Kind::Constant ? "constant" : "pressure-dependent",
                    std::string(load_path_name(path)).c_str(), ocr);
        for (int n : {10, 20, 40, 80}) std::printf("  %9.2e", error_vs_cvode(mcc, triaxial(path, ocr, n), "implicit"));
        std::printf("\n");
      }
  }
}

TEST_CASE("MCC drained: substep at 1e-8 (printed)", "[.diagnose]") {
  auto params = test::table1_cam_clay_params(Elasticity::Kind::PressureDependent);
  params.substep_tolerance = 1e-8;
  const Material mcc = ModifiedCamClay(params);
  for (double ocr : {1.0, 1.5}) {
    std::printf("substep 1e-8 drained OCR %.1f:", ocr);
    for (int n : {10, 20, 40, 80})
      std::printf("  %9.2e", error_vs_cvode(mcc, triaxial(LoadPath::TriaxialDrained, ocr, n), "substep"));
    std::printf("\n");
  }
}

TEST_CASE("MCC implicit: where the error is (printed)", "[.diagnose]") {
  auto params = test::table1_cam_clay_params(Elasticity::Kind::Constant);
  params.young_modulus = 1.2 * 1.68 * 200e3 / 0.019;  // K of the pressure-dependent law at 200 kPa
  const Material stiff = ModifiedCamClay(params);
  const Material soft = test::table1_cam_clay(Elasticity::Kind::PressureDependent);
  for (const Material* m : {&stiff, &soft})
    for (LoadPath path : {LoadPath::TriaxialDrained, LoadPath::TriaxialUndrained}) {
      const PointTest t = triaxial(path, 1.0, 20);
      const PointCurve ref = run_point_test(*m, t, kReferenceIntegrator), cur = run_point_test(*m, t, "implicit");
      std::printf("%s %s: %.2e\n", m == &stiff ? "constant E = K(200 kPa)" : "pressure-dependent",
                  std::string(load_path_name(path)).c_str(),
                  curve_errors(cur, as_reference(ref), path).max());
      for (std::size_t k = 0; k < ref.size(); k += (k < 4 ? 1 : 4))
        std::printf("  eps_a %.4f  q_ref %9.1f  q %9.1f  p_ref %9.1f  p %9.1f\n", ref[k].eps_a, ref[k].q, cur[k].q,
                    ref[k].p, cur[k].p);
    }
}
