// The closed-form references checked against independent facts: yield and critical-state
// conditions, limits with known solutions, and the GSL tools on hand-integrable cases.
#include <catch2/catch.hpp>
#include <cmath>

#include "closed_form_fixtures.h"
#include "verification/closed_form/cam_clay_compression.h"
#include "verification/closed_form/cam_clay_drained.h"
#include "verification/closed_form/cam_clay_undrained.h"
#include "verification/closed_form/drucker_prager_strain_path.h"
#include "verification/closed_form/drucker_prager_triaxial.h"
#include "verification/closed_form/gsl_numerics.h"

using namespace soilsph;
using namespace soilsph::verification;
using Kind = Elasticity::Kind;

TEST_CASE("GSL quadrature and root finding on hand-solvable cases", "[closed-form]") {
  CHECK(integrate([](double x) { return x * x; }, 0.0, 3.0) == Approx(9.0).epsilon(1e-13));
  // An end-point singularity like the NC undrained path's: ∫_0^1 dx/√(1−x) = 2.
  CHECK(integrate([](double x) { return 1.0 / std::sqrt(1.0 - x); }, 0.0, 1.0) == Approx(2.0).epsilon(1e-10));
  // A log singularity like the approach to the CSL: ∫_0^1 ln x dx = −1.
  CHECK(integrate([](double x) { return std::log(x); }, 0.0, 1.0) == Approx(-1.0).epsilon(1e-10));
  CHECK(find_root([](double x) { return x * x - 2.0; }, 0.0, 2.0) == Approx(std::sqrt(2.0)).epsilon(1e-14));
  CHECK_THROWS(find_root([](double x) { return x * x + 1.0; }, 0.0, 2.0));
}

TEST_CASE("D-P drained triaxial: the peak lies on the cone, the elastic branch is q = E eps_a",
          "[closed-form]") {
  const double p_i = 100e3;
  for (double cohesion : {0.0, 5e3}) {
    const DruckerPrager dp = test::table1_drucker_prager(cohesion, 5.0);
    const DruckerPragerDrainedTriaxial cf(dp, p_i);
    const double q = cf.peak_q();
    // On the path σ_r = −p_i: the peak state satisfies f = 0 (eq 17) evaluated on the full tensor.
    CHECK(dp.yield(test::triaxial_stress(p_i + q / 3.0, q)) == Approx(0.0).margin(1e-9 * q));
    const ReferencePoint elastic = cf.at(0.5 * cf.yield_strain());
    CHECK(elastic.q == Approx(1.0e6 * 0.5 * cf.yield_strain()));
    CHECK(elastic.eps_v == Approx(0.4 * 0.5 * cf.yield_strain()));  // (1 − 2ν) ε_a
    // Beyond the peak the stress stays and ψ > 0 dilates: ε_v decreases.
    const ReferencePoint a = cf.at(2.0 * cf.yield_strain()), b = cf.at(3.0 * cf.yield_strain());
    CHECK(a.q == Approx(q));
    CHECK(b.eps_v < a.eps_v);
  }
}

TEST_CASE("D-P strain paths: undrained plateau on the cone, elastic oedometer and isotropic lines",
          "[closed-form]") {
  const double p_i = 100e3;
  const DruckerPrager plain = test::table1_drucker_prager();
  const DruckerPragerStrainPath undrained(plain, p_i, 0.0, 1.0);
  // ψ = 0: constant p, q = 3G ε_a up to the cone at √3 · 3 α_φ p_i, then a plateau.
  const double G = 1.0e6 / 2.6, q_cone = std::sqrt(3.0) * 3.0 * plain.alpha_phi() * p_i;
  CHECK(undrained.at(0.01).q == Approx(3.0 * G * 0.01));
  CHECK(undrained.yield_strain() == Approx(q_cone / (3.0 * G)));
  CHECK(undrained.at(0.3).q == Approx(q_cone));
  CHECK(undrained.at(0.3).p == Approx(p_i));
  // c and ψ > 0: dilation at constant volume raises p'; the state stays on the cone.
  const DruckerPrager dilatant = test::table1_drucker_prager(5e3, 5.0);
  const DruckerPragerStrainPath cf(dilatant, p_i, 0.0, 1.0);
  for (double eps : {0.2, 0.3}) {
    const ReferencePoint r = cf.at(eps);
    CHECK(r.p > p_i);
    CHECK(dilatant.yield(test::triaxial_stress(r.p, r.q)) == Approx(0.0).margin(1e-9 * r.q));
  }
  // Oedometer: elastic K0 = ν/(1 − ν) below the cone; isotropic: p = p_i + K ε_v.
  const ReferencePoint oedo = DruckerPragerStrainPath(plain, p_i, 1.0, 2.0 / 3.0).at(0.05);
  const double sigma_a = oedo.p + 2.0 * oedo.q / 3.0 - p_i, sigma_r = oedo.p - oedo.q / 3.0 - p_i;
  CHECK(sigma_r / sigma_a == Approx(0.3 / 0.7));
  const double K = 1.0e6 / (3.0 * 0.4);
  CHECK(DruckerPragerStrainPath(plain, p_i, 3.0, 0.0).at(0.01).p == Approx(p_i + K * 0.03));
}

TEST_CASE("MCC undrained triaxial: vertical elastic path, yield-surface path, end on the CSL",
          "[closed-form]") {
  const double p0 = 100e3;
  for (Kind kind : {Kind::PressureDependent, Kind::Constant}) {
    for (double ocr : {1.0, 1.5}) {
      const ModifiedCamClay mcc = test::table1_cam_clay(kind);
      const CamClayUndrainedTriaxial cf(mcc, p0, ocr);
      if (kind == Kind::PressureDependent) {
        const double Lambda = (0.085 - 0.019) / 0.085;  // Wood (1990) eq 7.18-type result
        CHECK(cf.failure_p() == Approx(p0 * std::pow(ocr / 2.0, Lambda)).epsilon(1e-13));
      }
      CHECK(2.0 * cf.failure_p() == Approx(cf.pc_at(cf.failure_p())).epsilon(1e-10));  // CSL: p_c = 2p'
      // Elastic branch at constant p'; the yield point with p_c0 on the surface.
      CHECK(cf.at(0.5 * cf.yield_strain()).p == Approx(p0));
      CHECK(mcc.yield(test::triaxial_stress(p0, cf.yield_q()), ocr * p0) ==
            Approx(0.0).margin(1e-6 * p0 * p0));
      // Plastic states lie on the surface with their own p_c and approach the CSL.
      for (double eps : {0.005, 0.02, 0.1}) {
        const ReferencePoint r = cf.at(cf.yield_strain() + eps);
        CHECK(mcc.normalized_yield(test::triaxial_stress(r.p, r.q), r.p_c) == Approx(0.0).margin(1e-12));
      }
      const ReferencePoint end = cf.at(cf.yield_strain() + 1.0);
      CHECK(end.p == Approx(cf.failure_p()).epsilon(1e-6));
      CHECK(end.q / end.p == Approx(mcc.M()).epsilon(1e-6));
      // The quadrature is consistent with the root finding that inverts it.
      const ReferencePoint mid = cf.at(cf.yield_strain() + 0.01);
      CHECK(cf.strain_at(mid.p) == Approx(cf.yield_strain() + 0.01).epsilon(1e-10));
    }
  }
}

TEST_CASE("MCC drained triaxial: eps_v(q) satisfies the yield function, failure on the CSL",
          "[closed-form]") {
  const double p_i = 100e3;
  for (Kind kind : {Kind::PressureDependent, Kind::Constant}) {
    for (double ocr : {1.0, 1.5}) {
      const ModifiedCamClay mcc = test::table1_cam_clay(kind);
      const CamClayDrainedTriaxial cf(mcc, p_i, ocr);
      const double M = mcc.M();
      CHECK(cf.failure_q() == Approx(M * (p_i + cf.failure_q() / 3.0)));
      const double K = mcc.elasticity().at(p_i).K, kappa_star = 0.019 / 1.68, a = (0.085 - 0.019) / 1.68;
      for (double frac : {0.3, 0.7, 0.99}) {
        const double q = std::max(frac * cf.failure_q(), cf.yield_q());
        const double p = p_i + q / 3.0;
        // Independently: p_c from ε_v minus the elastic volume (inverting eq 27), then f(p, q, p_c) = 0.
        const double elastic =
            kind == Kind::PressureDependent ? kappa_star * std::log(p / p_i) : (p - p_i) / K;
        const double pc = ocr * p_i * std::exp((cf.volumetric_strain_at(q) - elastic) / a);
        CHECK(mcc.normalized_yield(test::triaxial_stress(p, q), pc) == Approx(0.0).margin(1e-12));
      }
      const ReferencePoint r = cf.at(0.05);
      CHECK(cf.axial_strain_at(r.q) == Approx(0.05).epsilon(1e-10));
      CHECK(cf.at(2.0).q == Approx(cf.failure_q()).epsilon(1e-6));
    }
  }
}

TEST_CASE("MCC isotropic compression: NCL slope lambda*, swelling slope kappa*", "[closed-form]") {
  const double p_i = 100e3, lambda_star = 0.085 / 1.68, kappa_star = 0.019 / 1.68;
  const ModifiedCamClay mcc = test::table1_cam_clay(Kind::PressureDependent);
  const CamClayIsotropicCompression cf(mcc, p_i, 2.0);
  const std::vector<double> eps = {0.0, 0.005, 0.04, 0.06, 0.05};
  const auto r = cf.curve(eps);
  // OC: elastic until p' = p_c0 = 2 p_i at ε_v = κ* ln 2, then the NCL.
  CHECK(r[1].p == Approx(p_i * std::exp(0.005 / kappa_star)).epsilon(1e-12));
  CHECK((r[3].eps_v - r[2].eps_v) / std::log(r[3].p / r[2].p) == Approx(lambda_star).epsilon(1e-12));
  CHECK(r[2].eps_v == Approx(kappa_star * std::log(2.0) + lambda_star * std::log(r[2].p / (2.0 * p_i))));
  CHECK((r[3].eps_v - r[4].eps_v) / std::log(r[3].p / r[4].p) == Approx(kappa_star).epsilon(1e-12));
  CHECK(r[4].p_c == Approx(r[3].p));
  // Constant elasticity: the NCL point from the root finder satisfies ε_v = Δp/K + (λ*−κ*) ln(p/p_c0).
  const ModifiedCamClay constant = test::table1_cam_clay(Kind::Constant);
  const double K = constant.elasticity().at(0.0).K;
  const auto c = CamClayIsotropicCompression(constant, p_i, 1.0).curve(std::vector<double>{0.05});
  CHECK(0.05 ==
        Approx((c[0].p - p_i) / K + (lambda_star - kappa_star) * std::log(c[0].p / p_i)).epsilon(1e-12));
}

TEST_CASE("MCC oedometer: K0 within bounds and equal to the rigid-plastic limit as kappa -> 0",
          "[closed-form]") {
  const ModifiedCamClay mcc = test::table1_cam_clay(Kind::PressureDependent);
  const double M = mcc.M();
  const double eta = cam_clay_k0_stress_ratio(mcc);
  CHECK(eta > 0.0);
  CHECK(eta < M);
  const double k0 = k0_from_stress_ratio(eta);
  CHECK(k0 < 1.0);
  CHECK(k0 > k0_from_stress_ratio(M));
  // κ → 0: no elastic strain, so 2η/(M² − η²) = 2/3 and η² + 3η − M² = 0.
  const double rigid = cam_clay_k0_stress_ratio(test::table1_cam_clay(Kind::PressureDependent, 1e-10));
  CHECK(rigid == Approx((-3.0 + std::sqrt(9.0 + 4.0 * M * M)) / 2.0).epsilon(1e-7));
  // Along the loading curve η tends to η_K0 and the slope in ε_a – ln σ'_a tends to λ*.
  for (double ocr : {1.0, 1.3}) {
    const CamClayOedometer cf(mcc, 100e3, ocr);
    const auto r = cf.curve(std::vector<double>{0.3, 0.31, 0.305});
    CHECK(r[0].q / r[0].p == Approx(eta).epsilon(1e-9));
    const auto sigma_a = [](const ReferencePoint& x) { return x.p + 2.0 * x.q / 3.0; };
    CHECK((r[1].eps_a - r[0].eps_a) / std::log(sigma_a(r[1]) / sigma_a(r[0])) ==
          Approx(0.085 / 1.68).epsilon(1e-9));
    // Elastic unloading: slope κ* against ln p'.
    CHECK((r[1].eps_a - r[2].eps_a) / std::log(r[1].p / r[2].p) == Approx(0.019 / 1.68).epsilon(1e-12));
    CHECK(mcc.normalized_yield(test::triaxial_stress(r[1].p, r[1].q), r[1].p_c) == Approx(0.0).margin(1e-12));
  }
}
