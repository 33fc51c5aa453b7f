// Elastic response against Hooke's law written in Lamé form, and the pressure-dependent law
// against its closed-form swelling line.
#include <catch2/catch.hpp>
#include <cmath>

#include "helpers.h"

using namespace soilsph;

namespace {
/// Hooke's law σ = λ tr(ε) I + 2μ ε with λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)): written independently
/// of the (K, G) form the library uses.
Mat3 hooke(double E, double nu, const Mat3& eps) {
  const double lame = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double mu = E / (2 * (1 + nu));
  return lame * eps.trace() * Mat3::Identity() + 2 * mu * eps;
}
}  // namespace

TEST_CASE("elastic increments follow Hooke's law for every model", "[elasticity]") {
  std::mt19937_64 rng(42);
  const LinearElastic linear({2000.0, 1.0e6, 0.3});
  const DruckerPrager dp(test::table1_drucker_prager(/*cohesion=*/1.0e6));
  const ModifiedCamClay mcc(test::table1_cam_clay(Elasticity::Kind::Constant));
  for (int trial = 0; trial < 200; ++trial) {
    const Mat3 d_eps = test::random_symmetric(rng, 1e-5);
    const Mat3 expected = hooke(1.0e6, 0.3, d_eps);
    State start;
    CHECK((linear.update(start, d_eps, Mat3::Zero()).stress - expected).norm() <= 1e-9 * expected.norm());
    // D-P with a large cohesion: the stress-free state is deep inside the cone.
    CHECK((dp.update(start, d_eps, Mat3::Zero()).stress - expected).norm() <= 1e-9 * expected.norm());
    // MCC well inside its ellipse: p = 50 kPa, p_c = 200 kPa.
    State inside;
    inside.stress = isotropic_stress(50e3);
    inside.pc = 200e3;
    const State after = mcc.update(inside, d_eps, Mat3::Zero());
    CHECK((after.stress - inside.stress - expected).norm() <= 1e-9 * expected.norm());
    CHECK(after.pc == inside.pc);
    CHECK(after.plastic_multiplier == 0.0);
  }
}

TEST_CASE("pressure-dependent elasticity integrates the swelling line exactly", "[elasticity]") {
  const double kappa = 0.019, e0 = 0.68, nu = 0.3, floor = 1e3;
  const Elasticity e = Elasticity::pressure_dependent(kappa, e0, nu, floor);
  SECTION("tangent moduli K = (1+e0) p / kappa and G from nu") {
    const Moduli m = e.at(100e3);
    CHECK(m.K == Approx((1 + e0) * 100e3 / kappa));
    CHECK(m.G == Approx(m.K * 3 * (1 - 2 * nu) / (2 * (1 + nu))));
    CHECK(e.at(10.0).K == Approx((1 + e0) * floor / kappa));  // the floor
  }
  SECTION("above the floor: ε_v = κ/(1+e0) ln(p/p_i)") {
    for (double ratio : {0.2, 0.5, 2.0, 10.0}) {
      const double d_eps_v = kappa / (1 + e0) * std::log(ratio);
      CHECK(e.pressure_after(100e3, d_eps_v) == Approx(100e3 * ratio).epsilon(1e-12));
    }
  }
  SECTION("through the floor the law is continuous and invertible") {
    // Unload from 10 kPa to the floor (log branch), then linearly to 500 Pa, and back.
    const double to_floor = kappa / (1 + e0) * std::log(floor / 10e3);
    const double linear = (500.0 - floor) * kappa / ((1 + e0) * floor);
    const double p = e.pressure_after(10e3, to_floor + linear);
    CHECK(p == Approx(500.0).epsilon(1e-12));
    CHECK(e.pressure_after(p, -(to_floor + linear)) == Approx(10e3).epsilon(1e-12));
  }
}

TEST_CASE("secant moduli keep their digits for tiny increments and their slope is their derivative",
          "[elasticity]") {
  const double kappa = 0.019, e0 = 0.68, nu = 0.3, floor = 1e3;
  const double kappa_star = kappa / (1 + e0);
  const Elasticity e = Elasticity::pressure_dependent(kappa, e0, nu, floor);
  SECTION("a 1e-13 volume change: the secant to round-off") {
    // Differences of pressures would keep only ~3 to 5 digits here (Δp ≈ 1e-8 Pa against p ≈ 1 Pa).
    CHECK(e.secant(1.0, 1e-13).K == Approx(floor / kappa_star).epsilon(1e-14));  // below the floor: linear
    // Above: K_sec = (p/κ*)(eˣ − 1)/x = (p/κ*)(1 + x/2 + O(x²)), x = dεv/κ*.
    const double x = -1e-13 / kappa_star;
    CHECK(e.secant(100e3, -1e-13).K == Approx(100e3 / kappa_star * (1 + x / 2)).epsilon(1e-14));
  }
  SECTION("the secant moduli's slope matches central differences of secant") {
    // Above the floor (series and closed-form branches), crossing it both ways, below it.
    for (auto [p, d_eps_v] : {std::pair{100e3, 1e-6},
                              {100e3, -2e-2},
                              {100e3, 5e-2},
                              {1.5e3, -2e-2},
                              {800.0, 3e-2},
                              {500.0, 1e-3}}) {
      const double h = 1e-6 * kappa_star;
      const double numeric = (e.secant(p, d_eps_v + h).K - e.secant(p, d_eps_v - h).K) / (2 * h);
      INFO("p " << p << ", dεv " << d_eps_v);
      const Moduli slope = e.volume_step(p, d_eps_v).secant_slope;
      CHECK(slope.K == Approx(numeric).epsilon(1e-6).margin(1e-6 * floor / kappa_star));
      CHECK(slope.G == Approx(slope.K * 3 * (1 - 2 * nu) / (2 * (1 + nu))));
    }
  }
}

TEST_CASE("volume_step gives pressure_after, at and secant in one call", "[elasticity]") {
  const Elasticity e = Elasticity::pressure_dependent(0.019, 0.68, 0.3, 1e3);
  // On the swelling line (the one-exponential branch), into the floor, below it, and x = 0.
  for (auto [p, d_eps_v] :
       {std::pair{100e3, 2e-2}, {100e3, -1e-6}, {100e3, 0.0}, {2e3, -3e-2}, {500.0, 1e-3}}) {
    INFO("p " << p << ", dεv " << d_eps_v);
    const ElasticVolumeStep step = e.volume_step(p, d_eps_v);
    CHECK(step.p == Approx(e.pressure_after(p, d_eps_v)).epsilon(1e-14));
    CHECK(step.tangent.K == Approx(e.at(e.pressure_after(p, d_eps_v)).K).epsilon(1e-14));
    CHECK(step.secant.G == Approx(e.secant(p, d_eps_v).G).epsilon(1e-14));
  }
}
