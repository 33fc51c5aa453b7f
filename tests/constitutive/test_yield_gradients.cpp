// Analytic yield-function gradients against central differences of the yield function.
#include <catch2/catch.hpp>

#include "helpers.h"

using namespace soilsph;

namespace {
/// Central-difference gradient of f(σ) over symmetric perturbations: each off-diagonal pair is
/// perturbed together, so the (i,j) and (j,i) entries share the derivative (∂f/∂σ_ij symmetric).
template <class F>
Mat3 central_difference_gradient(F f, const Mat3& sigma, double h) {
  Mat3 g;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j) {
      Mat3 e = Mat3::Zero();
      e(i, j) = e(j, i) = h;
      const double d = (f(sigma + e) - f(sigma - e)) / (2 * h);
      g(i, j) = g(j, i) = (i == j) ? d : d / 2;
    }
  }
  return g;
}
}  // namespace

TEST_CASE("Drucker-Prager yield and potential gradients match central differences", "[gradient]") {
  std::mt19937_64 rng(7);
  const double psi = 10.0 * M_PI / 180.0;
  // g = √J2 + α_ψ I1: matched α_ψ = tanψ/√(9 + 12 tan²ψ) (default), printed eq 20 α_ψ = 3 sinψ.
  const auto [potential, alpha_psi] = GENERATE_COPY(
      std::pair(PlasticPotential::Matched, std::tan(psi) / std::sqrt(9 + 12 * std::tan(psi) * std::tan(psi))),
      std::pair(PlasticPotential::PaperEq20, 3 * std::sin(psi)));
  DruckerPrager::Params params = test::table1_drucker_prager_params(5e3, 10.0);
  params.plastic_potential = potential;
  const DruckerPrager dp(params);
  CHECK(dp.alpha_psi() == Approx(alpha_psi).epsilon(1e-14));
  for (int trial = 0; trial < 100; ++trial) {
    const Mat3 sigma = isotropic_stress(100e3) + test::random_symmetric(rng, 50e3);
    const Mat3 fd = central_difference_gradient([&](const Mat3& s) { return dp.yield(s); }, sigma, 1.0);
    CHECK((dp.yield_gradient(sigma) - fd).norm() <= 1e-6 * fd.norm());
    auto g = [&](const Mat3& s) { return std::sqrt(second_deviatoric_invariant(s)) + alpha_psi * s.trace(); };
    const Mat3 fd_g = central_difference_gradient(g, sigma, 1.0);
    CHECK((dp.flow_direction(sigma) - fd_g).norm() <= 1e-6 * fd_g.norm());
  }
}

TEST_CASE("the matched D-P potential with psi = phi is the yield function: associated flow", "[gradient]") {
  DruckerPrager::Params params = test::table1_drucker_prager_params(5e3, 35.0);
  REQUIRE(params.friction_angle == 35.0);
  const DruckerPrager dp(params);
  CHECK(dp.alpha_psi() == dp.alpha_phi());
  std::mt19937_64 rng(5);
  const Mat3 sigma = isotropic_stress(100e3) + test::random_symmetric(rng, 50e3);
  CHECK((dp.flow_direction(sigma) - dp.yield_gradient(sigma)).norm() == 0.0);
}

TEST_CASE("Modified Cam-Clay yield gradient and hardening modulus match central differences", "[gradient]") {
  std::mt19937_64 rng(11);
  const ModifiedCamClay mcc(test::table1_cam_clay(Elasticity::Kind::PressureDependent));
  for (int trial = 0; trial < 100; ++trial) {
    const Mat3 sigma = isotropic_stress(100e3) + test::random_symmetric(rng, 40e3);
    const double pc = 150e3;
    const Mat3 fd = central_difference_gradient([&](const Mat3& s) { return mcc.yield(s, pc); }, sigma, 1.0);
    CHECK((mcc.yield_gradient(sigma, pc) - fd).norm() <= 1e-6 * fd.norm());
    // H = −∂f/∂p_c · dp_c/dλ, with dp_c/dλ = θ p_c (−tr n) from eq 27 and the flow rule.
    const double h = 1.0;
    const double df_dpc = (mcc.yield(sigma, pc + h) - mcc.yield(sigma, pc - h)) / (2 * h);
    const Mat3 n = mcc.flow_direction(sigma, pc);
    const double dpc_dlambda = mcc.hardening_exponent() * pc * volumetric_strain(n);
    CHECK(mcc.hardening_modulus(sigma, pc) == Approx(-df_dpc * dpc_dlambda).epsilon(1e-6));
  }
}

TEST_CASE("MCC slope M and D-P constants follow eq 26 and eq 19", "[gradient]") {
  const double phi = 35.0 * M_PI / 180.0;
  const ModifiedCamClay mcc(test::table1_cam_clay(Elasticity::Kind::Constant));
  CHECK(mcc.M() == Approx(6 * std::sin(phi) / (3 - std::sin(phi))));
  // On the critical-state line (q = M p, p = p_c/2) the yield surface has its top: f = 0, ∂f/∂p = 0.
  const double p = 50e3;
  Mat3 sigma = isotropic_stress(p);
  sigma(0, 0) -= mcc.M() * p;  // axial compression adds q = M p
  sigma += mcc.M() * p / 3 * Mat3::Identity();  // keep p
  CHECK(mean_pressure(sigma) == Approx(p));
  CHECK(deviatoric_stress(sigma) == Approx(mcc.M() * p));
  CHECK(mcc.yield(sigma, 2 * p) == Approx(0.0).margin(1e-6 * p * p));
  CHECK(mcc.yield_gradient(sigma, 2 * p).trace() == Approx(0.0).margin(1e-9 * p));

  const DruckerPrager dp(test::table1_drucker_prager(10e3));
  const double root = std::sqrt(9 + 12 * std::tan(phi) * std::tan(phi));
  CHECK(dp.alpha_phi() == Approx(std::tan(phi) / root));
  CHECK(dp.k_c() == Approx(3 * 10e3 / root));
}

TEST_CASE("MCC's initial preconsolidation puts a deviatoric state on its ellipse, times OCR", "[gradient]") {
  // The ellipse q² = M² p (p_c − p) through (p, q) = (100, 60) kPa in triaxial compression gives
  // p_c = p + q²/(M² p); with OCR 2 the surface is twice as large. Stress is tension-positive.
  const ModifiedCamClay mcc(test::table1_cam_clay(Elasticity::Kind::Constant));
  const double p = 100e3, q = 60e3;
  Mat3 sigma = Mat3::Zero();
  sigma.diagonal() << -(p + 2.0 * q / 3.0), -(p - q / 3.0), -(p - q / 3.0);
  const double on_surface = mcc.initial_preconsolidation(sigma, 1.0, 0.0);
  CHECK(mcc.yield(sigma, on_surface) == Approx(0.0).margin(1e-6 * p * p));
  const double sin_phi = std::sin(test::table1_cam_clay_params().friction_angle * M_PI / 180.0);
  const double M = 6.0 * sin_phi / (3.0 - sin_phi);  // eq 26
  CHECK(on_surface == Approx(p + q * q / (M * M * p)).epsilon(1e-12));
  CHECK(mcc.initial_preconsolidation(sigma, 2.0, 0.0) == Approx(2.0 * on_surface).epsilon(1e-12));
}
