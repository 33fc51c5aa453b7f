// Duvaut–Lions relaxation (constitutive/viscoplastic_relaxation.h) against the closed forms of its
// rate equation on a perfectly plastic soil in simple shear, and its limits.
#include <catch2/catch.hpp>
#include <cmath>

#include "constitutive/viscoplastic_relaxation.h"
#include "tests/constitutive/helpers.h"

using namespace soilsph;

namespace {
// D-P in simple shear at constant p: with ψ = 0 the flow is deviatoric, p stays p0 and the yield
// shear stress is τ_y = k + 3α p0 (f = α I1 + √J2 − k, √J2 = |σ_xy| in pure shear), with the
// paper's plane-strain match α = tan φ / √(9 + 12 tan² φ), k = 3c / √(9 + 12 tan² φ) (eq 17–18).
constexpr double kE = 1.0e8, kNu = 0.3, kPhi = 35.0, kC = 1.0e4, kP0 = 1.0e5;
constexpr double kG = kE / (2.0 * (1.0 + kNu));

DruckerPrager shear_soil() {
  DruckerPrager::Params p = test::table1_drucker_prager_params(kC, 0.0);
  p.young_modulus = kE;
  p.integrator = Integrator::Implicit;
  return DruckerPrager(p);
}

double yield_shear_stress() {
  const double t = std::tan(kPhi * M_PI / 180.0), root = std::sqrt(9.0 + 12.0 * t * t);
  return 3.0 * kC / root + 3.0 * (t / root) * kP0;
}

Mat3 simple_shear(double gamma) {
  Mat3 d = Mat3::Zero();
  d(0, 1) = d(1, 0) = 0.5 * gamma;
  return d;
}

State isotropic_start() {
  State s;
  s.stress = -kP0 * Mat3::Identity();
  return s;
}

/// One viscoplastic step of the model.
template <class Model>
State step(const Model& model, const State& s, const Mat3& d_eps, double dt, double tau) {
  return relax_viscoplastically(model.elasticity(), s, d_eps, Mat3::Zero(), model.update(s, d_eps, Mat3::Zero()),
                                dt / tau);
}

/// Largest |σ_xy − closed form| over a shear at rate γ̇ to t_end in steps dt, where the rate equation
/// σ̇_xy = Gγ̇ − (σ_xy − τ_y)/τ past yield (t_y = τ_y/(Gγ̇)) gives
/// σ_xy = Gγ̇t before t_y and τ_y + Gγ̇τ (1 − exp(−(t − t_y)/τ)) after it.
double shear_error(double dt, double rate, double tau, double t_end) {
  const DruckerPrager model = shear_soil();
  const double ty = yield_shear_stress(), t_yield = ty / (kG * rate);
  State s = isotropic_start();
  double worst = 0.0;
  const int n = static_cast<int>(std::lround(t_end / dt));
  for (int k = 1; k <= n; ++k) {
    s = step(model, s, simple_shear(rate * dt), dt, tau);
    const double t = k * dt;
    const double exact = t < t_yield ? kG * rate * t : ty + kG * rate * tau * (1.0 - std::exp(-(t - t_yield) / tau));
    worst = std::max(worst, std::abs(s.stress(0, 1) - exact));
    REQUIRE(mean_pressure(s.stress) == Approx(kP0).epsilon(1e-12));
  }
  return worst;
}
}  // namespace

TEST_CASE("Duvaut-Lions: a steady shear rate past yield builds the overstress G rate tau (1 - exp(-t/tau))",
          "[viscoplastic]") {
  // γ̇ = 1/s, τ = 1 ms: yield at 1.6 ms, then 8 τ of relaxation; the overstress tends to Gγ̇τ = 38 kPa.
  const double rate = 1.0, tau = 1e-3, t_end = 0.01, scale = kG * rate * tau;
  const double coarse = shear_error(1e-5, rate, tau, t_end), fine = shear_error(5e-6, rate, tau, t_end);
  // Backward Euler of the rate equation: first order in Δt/τ.
  CHECK(coarse < 0.01 * scale);
  CHECK(coarse / fine == Approx(2.0).margin(0.3));
  // Without relaxation (τ → 0) the stress would sit on τ_y: the overstress is there.
  const DruckerPrager model = shear_soil();
  State s = isotropic_start();
  for (int k = 0; k < 1000; ++k) s = step(model, s, simple_shear(rate * 1e-5), 1e-5, tau);
  const double t_yield = yield_shear_stress() / (kG * rate);
  CHECK(s.stress(0, 1) - yield_shear_stress() == Approx(scale * (1.0 - std::exp(-(t_end - t_yield) / tau))).epsilon(0.01));
}

TEST_CASE("Duvaut-Lions: the steady-rate fixed point is the continuum's overstress exactly", "[viscoplastic]") {
  // X_{n+1} = X_n: (1 + r) σ = σ + GΔγ + r τ_y gives σ − τ_y = GΔγ/r = Gγ̇τ for any Δt.
  const DruckerPrager model = shear_soil();
  for (const double dt : {1e-5, 1e-4, 1e-3}) {
    const double rate = 1.0, tau = 1e-3;
    State s = isotropic_start();
    for (int k = 0; k < 200000 && k * dt < 60 * tau + 0.01; ++k) s = step(model, s, simple_shear(rate * dt), dt, tau);
    CHECK(s.stress(0, 1) - yield_shear_stress() == Approx(kG * rate * tau).epsilon(1e-9));
  }
}

TEST_CASE("Duvaut-Lions: at rest the overstress decays as exp(-t/tau)", "[viscoplastic]") {
  const DruckerPrager model = shear_soil();
  const double tau = 1e-3, dt = 1e-6;
  State s = isotropic_start();
  s.stress(0, 1) = s.stress(1, 0) = yield_shear_stress() + 1.0e4;  // 10 kPa above the surface
  for (int k = 0; k < 2000; ++k) s = step(model, s, Mat3::Zero(), dt, tau);  // 2 τ
  CHECK(s.stress(0, 1) - yield_shear_stress() == Approx(1.0e4 * std::exp(-2.0)).epsilon(2e-3));
}

TEST_CASE("Duvaut-Lions: tau -> 0 is the model, tau -> infinity elasticity, and elastic steps are the model's",
          "[viscoplastic]") {
  const DruckerPrager dp = shear_soil();
  const State start = isotropic_start();
  const Mat3 d = simple_shear(0.01);  // far past yield
  const State inviscid = dp.update(start, d, Mat3::Zero());
  const State fast = relax_viscoplastically(dp.elasticity(), start, d, Mat3::Zero(), inviscid, 1e12);
  const State slow = relax_viscoplastically(dp.elasticity(), start, d, Mat3::Zero(), inviscid, 1e-12);
  CHECK((fast.stress - inviscid.stress).norm() < 1e-6 * inviscid.stress.norm());
  CHECK(slow.stress(0, 1) == Approx(kG * 0.01).epsilon(1e-9));
  CHECK(slow.plastic_shear_strain < 1e-12);
  // An increment the model takes elastically is left as it is for any τ: the trial follows the
  // model's own elastic law (exact pressure, secant G), here MCC's pressure-dependent one, rotated.
  for (const auto kind : {Elasticity::Kind::PressureDependent, Elasticity::Kind::Constant}) {
    ModifiedCamClay::Params params = test::table1_cam_clay_params(kind);
    params.integrator = Integrator::Implicit;
    const ModifiedCamClay mcc(params);
    State s;
    s.stress = -2.0e5 * Mat3::Identity();
    s.pc = 4.0e5;  // OCR 2: inside the surface
    Mat3 unload = Mat3::Zero();
    unload(0, 0) = 2e-3, unload(1, 1) = 1e-3, unload(0, 1) = unload(1, 0) = 5e-4;  // swelling and shear
    Mat3 spin = Mat3::Zero();
    spin(0, 1) = 0.02, spin(1, 0) = -0.02;
    const State model_step = mcc.update(s, unload, spin);
    REQUIRE(model_step.plastic_multiplier == 0.0);
    const State relaxed = relax_viscoplastically(mcc.elasticity(), s, unload, spin, model_step, 0.3);
    CHECK((relaxed.stress - model_step.stress).norm() < 1e-9 * model_step.stress.norm());
    CHECK(relaxed.pc == Approx(model_step.pc).epsilon(1e-14));
  }
}

TEST_CASE("Duvaut-Lions: p_c relaxes with the stress (MCC compression past the surface)", "[viscoplastic]") {
  ModifiedCamClay::Params params = test::table1_cam_clay_params(Elasticity::Kind::Constant);
  params.integrator = Integrator::Implicit;
  const ModifiedCamClay mcc(params);
  State s;
  s.stress = -1.0e5 * Mat3::Identity();
  s.pc = 1.0e5;  // NC, on the surface
  const Mat3 d = -1e-3 * Mat3::Identity();
  const State inviscid = mcc.update(s, d, Mat3::Zero());
  REQUIRE(inviscid.pc > s.pc);
  const double r = 0.5;
  const State relaxed = relax_viscoplastically(mcc.elasticity(), s, d, Mat3::Zero(), inviscid, r);
  // Between the start (the trial's p_c) and the model's, at r/(1 + r) of the way, and the stress
  // outside the model's surface (an overstress) with the pressure between the trial's and the model's.
  CHECK(relaxed.pc == Approx(s.pc + r / (1.0 + r) * (inviscid.pc - s.pc)).epsilon(1e-14));
  CHECK(mcc.yield(relaxed.stress, relaxed.pc) > 0.0);
  const double p_trial = 1.0e5 + mcc.elasticity().at(1.0e5).K * 3e-3;
  CHECK(mean_pressure(relaxed.stress) > mean_pressure(inviscid.stress));
  CHECK(mean_pressure(relaxed.stress) < p_trial);
}
