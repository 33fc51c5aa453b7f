// D-P dilatancy: the drained post-peak ratio dε_v/dε_a of the material-point driver, for every
// integrator and the CVODE reference, against the flow rule's closed form (docs/method/derivations.md,
// "D-P plastic potential"). Expected values come from the formula, evaluated here from ψ alone.
#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>
#include <string>

#include "closed_form_fixtures.h"
#include "constitutive/tensor.h"
#include "verification/closed_form/drucker_prager_triaxial.h"
#include "verification/point_test.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
constexpr double kDegree = M_PI / 180.0;

/// α_ψ, the I1 coefficient of g = √J2 + α_ψ I1: matched like α_φ (eq 19), or 3 sinψ (eq 20).
double alpha_psi(PlasticPotential potential, double psi_degrees) {
  const double psi = psi_degrees * kDegree;
  if (potential == PlasticPotential::PaperEq20) return 3.0 * std::sin(psi);
  return std::tan(psi) / std::sqrt(9.0 + 12.0 * std::tan(psi) * std::tan(psi));
}

/// Drained triaxial compression at perfect plasticity, compression-positive: per unit dλ
/// dε_a = 1/√3 − α_ψ, dε_v = −3 α_ψ (the elastic strain rates vanish at the fixed peak stress).
double dilatancy_ratio(PlasticPotential potential, double psi_degrees) {
  const double a = alpha_psi(potential, psi_degrees);
  return -3.0 * a / (1.0 / std::sqrt(3.0) - a);
}

/// The same ratio without the hand derivation: the flow direction ∂g/∂σ of g = √J2 + α I1 by central
/// differences at a triaxial compression stress (σ_a = −300 kPa, σ_r = −100 kPa, tension-positive),
/// then dε_a = −∂g/∂σ_a and dε_v = −tr ∂g/∂σ (compression-positive).
double numerical_dilatancy_ratio(double alpha) {
  const auto g = [alpha](const Mat3& s) { return std::sqrt(second_deviatoric_invariant(s)) + alpha * s.trace(); };
  Mat3 sigma = Mat3::Zero();
  sigma.diagonal() << -300e3, -100e3, -100e3;
  const double h = 1.0;  // Pa
  double gradient[3];
  for (int k = 0; k < 3; ++k) {
    Mat3 up = sigma, down = sigma;
    up(k, k) += h, down(k, k) -= h;
    gradient[k] = (g(up) - g(down)) / (2.0 * h);
  }
  return -(gradient[0] + gradient[1] + gradient[2]) / -gradient[0];
}

DruckerPrager table1_with(PlasticPotential potential, double psi_degrees) {
  DruckerPrager::Params params = test::table1_drucker_prager_params(0.0, psi_degrees);
  params.plastic_potential = potential;
  return DruckerPrager(params);
}

/// dε_v/dε_a between the last two tenths of a drained triaxial test to ε_a = 0.3 (the Table 1 peak
/// is at ε_a ≈ 0.14, so both rows are far past it).
double driver_ratio(const DruckerPrager& model, std::string_view integrator) {
  PointTest test;
  test.path = LoadPath::TriaxialDrained;
  test.p_initial = 100e3;
  test.strain_targets = {0.3};
  test.increments = 100;
  const PointCurve curve = run_point_test(model, test, integrator);
  const PointRecord& a = curve[curve.size() - 11];
  const PointRecord& b = curve.back();
  REQUIRE(a.eps_a > 1.5 * DruckerPragerDrainedTriaxial(model, test.p_initial).yield_strain());
  return (b.eps_v - a.eps_v) / (b.eps_a - a.eps_a);
}
}  // namespace

TEST_CASE("the D-P closed forms of the dilatancy ratio: known values and the sign change of eq 20",
          "[dilatancy]") {
  using enum PlasticPotential;
  // ψ = 0: no plastic volume change under either potential.
  CHECK(dilatancy_ratio(Matched, 0.0) == 0.0);
  CHECK(dilatancy_ratio(PaperEq20, 0.0) == 0.0);
  // ψ = φ: the matched potential is the yield function (α_ψ = α_φ), associated flow.
  CHECK(alpha_psi(Matched, 35.0) == Approx(table1_with(Matched, 0.0).alpha_phi()));
  // The printed potential's axial rate 1/√3 − 3 sinψ vanishes at sinψ = 1/(3√3), ψ ≈ 11.1°.
  const double psi_zero = std::asin(1.0 / (3.0 * std::sqrt(3.0))) / kDegree;
  CHECK(psi_zero == Approx(11.0958).epsilon(1e-5));
  // The hand-derived ratio against the potential's gradient taken numerically, for both potentials.
  for (double psi : {0.0, 5.0, 10.0, 12.0, 20.0, 30.0}) {
    INFO("psi = " << psi);
    CHECK(dilatancy_ratio(PaperEq20, psi) ==
          Approx(numerical_dilatancy_ratio(3.0 * std::sin(psi * kDegree))).epsilon(1e-6).margin(1e-9));
    CHECK(dilatancy_ratio(Matched, psi) ==
          Approx(numerical_dilatancy_ratio(alpha_psi(Matched, psi))).epsilon(1e-6).margin(1e-9));
  }
  CHECK(dilatancy_ratio(PaperEq20, 10.0) < -20.0);  // just below the sign change: a huge dilation
  CHECK(dilatancy_ratio(PaperEq20, 12.0) > 0.0);  // past the sign change: "dilation" compacts
  // The matched potential is finite and dilating for every ψ up to 90°: α_ψ ≤ 1/√12 < 1/√3.
  CHECK(alpha_psi(Matched, 89.999) < 1.0 / std::sqrt(12.0));
  // Plane strain with no out-of-plane plastic strain: the matched D-P flow dilates like Mohr–Coulomb
  // with ψ, dε_v^p / dγ_max^p = 3 α_ψ / √(1 − 3 α_ψ²) = sinψ.
  for (double psi : {5.0, 10.0, 20.0, 30.0}) {
    const double a = alpha_psi(Matched, psi);
    CHECK(3.0 * a / std::sqrt(1.0 - 3.0 * a * a) == Approx(std::sin(psi * kDegree)).epsilon(1e-12));
  }
}

TEST_CASE("the D-P model and the closed form of verification/ follow the chosen potential", "[dilatancy]") {
  using enum PlasticPotential;
  for (const auto potential : {Matched, PaperEq20}) {
    for (double psi : {0.0, 5.0, 10.0}) {
      INFO("potential " << plastic_potential_name(potential) << ", psi = " << psi);
      const DruckerPrager dp = table1_with(potential, psi);
      CHECK(dp.alpha_psi() == Approx(alpha_psi(potential, psi)).epsilon(1e-14));
      const DruckerPragerDrainedTriaxial cf(dp, 100e3);
      const double ratio = (cf.at(0.3).eps_v - cf.at(0.25).eps_v) / 0.05;
      CHECK(ratio == Approx(dilatancy_ratio(potential, psi)).epsilon(1e-12).margin(1e-12));
    }
  }
}

TEST_CASE("drained post-peak dilatancy of every integrator and CVODE equals the flow rule's closed form",
          "[dilatancy]") {
  // Measured: every scheme and CVODE within 1e-13 relative (round-off; the post-peak stress is fixed,
  // so every scheme integrates the plastic flow exactly). The bounds are the verification cases'
  // (1e-8 here; CVODE's 1e-5, its case tolerance against closed forms).
  const auto check = [](PlasticPotential potential, double psi) {
    const DruckerPrager dp = table1_with(potential, psi);
    const double expected = dilatancy_ratio(potential, psi);
    for (const std::string integrator : {"explicit", "substep", "implicit", "cvode"}) {
      const double tolerance = integrator == "cvode" ? 1e-5 : 1e-8;
      const double ratio = driver_ratio(dp, integrator);
      INFO("potential " << plastic_potential_name(potential) << ", psi = " << psi << ", " << integrator
                        << ": " << std::setprecision(12) << ratio << " against " << expected
                        << " (difference " << std::setprecision(2) << ratio - expected << ")");
      CHECK(ratio == Approx(expected).epsilon(tolerance).margin(tolerance));
    }
  };
  SECTION("matched potential (the default), psi = 0, 10, 20, 30 degrees") {
    REQUIRE(test::table1_drucker_prager_params().plastic_potential == PlasticPotential::Matched);
    for (double psi : {0.0, 10.0, 20.0, 30.0}) check(PlasticPotential::Matched, psi);
  }
  SECTION("the printed eq 20 (paper-eq20), psi = 5 and 10 degrees") {
    for (double psi : {5.0, 10.0}) check(PlasticPotential::PaperEq20, psi);
  }
}
