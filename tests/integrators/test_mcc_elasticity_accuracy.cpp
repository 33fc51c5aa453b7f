// MCC `implicit` against the CVODE reference on drained and undrained triaxial paths to ε_a = 0.1,
// for both elasticities (constant E of Table 1; K = (1+e0)p/κ) and OCR 1 and 1.5 from p0 = 200 kPa:
// our goal is a relative error ≤ 1e-3 (verification/report/curve_errors) with
// 20 increments in all eight cases.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "constitutive/integrators/implicit_cam_clay.h"
#include "tests/common/table1_materials.h"
#include "tests/integrators/stiff_clay_paths.h"
#include "verification/point_test.h"
#include "verification/report/curve_errors.h"

using namespace soilsph;
using namespace soilsph::verification;
using soilsph::test::error_vs_cvode;
using soilsph::test::triaxial;

namespace {
ModifiedCamClay table1(Elasticity::Kind kind, double implicit_tolerance) {
  auto params = test::table1_cam_clay_params(kind);
  params.implicit_tolerance = implicit_tolerance;
  return ModifiedCamClay(params);
}

}  // namespace

TEST_CASE(
    "MCC implicit with implicit_tolerance = 1e-3: undrained triaxial within 1e-3 of CVODE in 20 increments",
    "[integrators][cvode]") {
  // Our goal: ≤ 1e-3 in 20 increments. The expectation is CVODE's curve; the bound is that goal.
  // implicit_tolerance bounds the step-doubling estimate of each doubled sub-increment's error, and
  // the result kept is the doubling's local extrapolation (O(h⁴) where the estimate is O(h³)), so the
  // path errs well below the tolerance: 1e-3 gives 1.2e-4 (OCR 1) and 4.4e-4 (OCR 1.5) on the stiff
  // clay, 1e-4 gives 6e-6 and 8e-6. (Before the extrapolation 1e-3 gave 1.05e-3, 1e-4 gave 2e-4.)
  // Without control the pressure-dependent clay (K = 17.7 MPa at 200 kPa, 21x the Table 1 constant
  // E) errs by 8.4e-3 (OCR 1) and 2.5e-3 (OCR 1.5): it reaches the critical state within ε_a ≈ 0.02,
  // four increments, which the midpoint rule cannot resolve (a constant E of the same stiffness errs
  // by 1.9e-2: stiffness, not the elastic law, sets the error).
  for (auto kind : {Elasticity::Kind::Constant, Elasticity::Kind::PressureDependent})
    for (double ocr : {1.0, 1.5}) {
      INFO((kind == Elasticity::Kind::Constant ? "constant" : "pressure-dependent") << ", OCR " << ocr);
      const double error =
          error_vs_cvode(table1(kind, 1e-3), triaxial(LoadPath::TriaxialUndrained, ocr, 20), "implicit");
      CHECK(error <= 1e-3);
    }
}

TEST_CASE("MCC implicit with implicit_tolerance = 1e-3, drained triaxial: constant E within 1e-3 of CVODE in 20 "
          "increments; K proportional to p at the driver's limit",
          "[integrators][cvode]") {
  for (double ocr : {1.0, 1.5}) {
    INFO("OCR " << ocr);
    CHECK(error_vs_cvode(table1(Elasticity::Kind::Constant, 1e-3), triaxial(LoadPath::TriaxialDrained, ocr, 20),
                         "implicit") <= 1e-3);
    // The drained driver imposes a straight strain path inside each increment and holds σ_r only at
    // its end; CVODE holds σ_r throughout. For the stiff clay that path difference is 2.5e-3 (OCR 1)
    // and 1.6e-3 (OCR 1.5) at 20 increments, whatever the integrator: substep at tolerance 1e-8 errs
    // by the same. Our goal (1e-3) is not met here without the driver's sub-steps
    // (test_mcc_path_substeps.cpp); the controlled implicit at 1e-4 is within 10 % of the near-exact
    // integration of the driver's path.
    auto accurate = test::table1_cam_clay_params(Elasticity::Kind::PressureDependent);
    accurate.substep_tolerance = 1e-8;
    const PointTest t = triaxial(LoadPath::TriaxialDrained, ocr, 20);
    const double driver_limit = error_vs_cvode(ModifiedCamClay(accurate), t, "substep");
    const double controlled = error_vs_cvode(table1(Elasticity::Kind::PressureDependent, 1e-4), t, "implicit");
    INFO("substep 1e-8: " << driver_limit << ", implicit 1e-4: " << controlled);
    CHECK(driver_limit > 1e-3);
    CHECK(std::abs(controlled - driver_limit) <= 0.1 * driver_limit);
  }
}

TEST_CASE("MCC controlled implicit: a split increment reports the single return's tangent, near the derivative "
          "of the update",
          "[integrators]") {
  // An undrained NC increment of 1e-2 from the tip: at tolerance 1e-5 the stiff clay needs several
  // sub-increments (checked below: the update differs from the single return). The tangent is that
  // of one return over the whole increment (exact where the increment is not split; for the driver's
  // Newton otherwise, which converges on the residual whatever the tangent).
  // (table1() keeps the helper's `explicit`, whose tangent is differences of its own update: this
  // test needs `implicit` set, as `point --integrator implicit` does.)
  auto params = test::table1_cam_clay_params(Elasticity::Kind::PressureDependent);
  params.integrator = Integrator::Implicit;
  params.implicit_tolerance = 1e-5;
  const ModifiedCamClay mcc(params);
  params.implicit_tolerance = 0.0;
  const ModifiedCamClay single(params);
  State start;
  start.stress = isotropic_stress(200e3);
  start.pc = 200e3;
  Mat3 d = Mat3::Zero();
  d(0, 0) = -1e-2, d(1, 1) = d(2, 2) = 5e-3;
  const Mat6 tangent = mcc.consistent_tangent(start, d);
  CHECK(tangent == single.consistent_tangent(start, d));
  // The driver's tangent (taken without running the sub-increments) is the one the controlled
  // update itself writes.
  Mat6 written;
  implicit_update(mcc, start, d, &written);
  CHECK(tangent == written);
  const Mat3 split = mcc.update(start, d, Mat3::Zero()).stress, whole = single.update(start, d, Mat3::Zero()).stress;
  CHECK((split - whole).norm() > 1e-3 * whole.norm());
  // The derivative of the composed update by central differences (the split is piecewise constant
  // in Δε, so the differences see one schedule). The single return's tangent is a search direction
  // within 20 % of it here (13 % measured, see the INFO). Before this test set `implicit`, both sides
  // were differences of the `explicit` update, and the check said nothing.
  const Vec6 base = strain_to_voigt(d);
  const double h = 1e-9;
  Mat6 differences;
  for (int k = 0; k < 6; ++k) {
    Vec6 plus = base, minus = base;
    plus(k) += h, minus(k) -= h;
    differences.col(k) = (stress_to_voigt(mcc.update(start, strain_from_voigt(plus), Mat3::Zero()).stress) -
                          stress_to_voigt(mcc.update(start, strain_from_voigt(minus), Mat3::Zero()).stress)) /
                         (2.0 * h);
  }
  INFO("relative distance " << (tangent - differences).norm() / differences.norm());
  CHECK((tangent - differences).norm() <= 0.2 * differences.norm());
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
