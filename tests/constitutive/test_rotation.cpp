// The Jaumann (spin) terms: a rigid spin keeps p and q, and the rotation agrees with the paper's
// first-order terms σω^T + ωσ of eq 21/28.
#include <catch2/catch.hpp>

#include "helpers.h"

using namespace soilsph;

TEST_CASE("a pure rigid-body spin leaves p and q unchanged for every model", "[rotation]") {
  std::mt19937_64 rng(3);
  const DruckerPrager dp(test::table1_drucker_prager(20e3));
  const ModifiedCamClay mcc(test::table1_cam_clay(Elasticity::Kind::PressureDependent));
  State s;
  s.stress = isotropic_stress(100e3) + test::random_symmetric(rng, 20e3);
  s.pc = 300e3;
  const double p0 = mean_pressure(s.stress), q0 = deviatoric_stress(s.stress);
  State a = s, b = s;
  for (int k = 0; k < 1000; ++k) {
    const Mat3 spin = test::random_skew(rng, 0.05);
    a = dp.update(a, Mat3::Zero(), spin);
    b = mcc.update(b, Mat3::Zero(), spin);
  }
  CHECK(mean_pressure(a.stress) == Approx(p0).epsilon(1e-12));
  CHECK(deviatoric_stress(a.stress) == Approx(q0).epsilon(1e-12));
  CHECK(mean_pressure(b.stress) == Approx(p0).epsilon(1e-12));
  CHECK(deviatoric_stress(b.stress) == Approx(q0).epsilon(1e-12));
  CHECK(b.pc == s.pc);
}

TEST_CASE("the Cayley rotation is orthogonal, first-order equal to the paper's terms", "[rotation]") {
  std::mt19937_64 rng(9);
  const Mat3 sigma = test::random_symmetric(rng, 1.0);
  SECTION("a quarter turn about z swaps sigma_xx and sigma_yy") {
    // Cayley rotation angle is 2 atan(w/2): w = 2 gives 90 degrees.
    Mat3 w = Mat3::Zero();
    w(0, 1) = -2.0, w(1, 0) = 2.0;
    const Mat3 Q = spin_rotation(w);
    CHECK((Q * Q.transpose() - Mat3::Identity()).norm() < 1e-14);
    const Mat3 rotated = Q * sigma * Q.transpose();
    CHECK(rotated(0, 0) == Approx(sigma(1, 1)));
    CHECK(rotated(1, 1) == Approx(sigma(0, 0)));
    CHECK(rotated(2, 2) == Approx(sigma(2, 2)));
  }
  SECTION("small spins: Q σ Qᵀ − σ = σωᵀ + ωσ + O(ω²)") {
    const Mat3 w_unit = test::random_skew(rng, 1.0);
    for (double eps : {1e-2, 1e-3}) {
      const Mat3 w = eps * w_unit;
      const Mat3 Q = spin_rotation(w);
      const Mat3 paper = sigma * w.transpose() + w * sigma;
      const double error = (Q * sigma * Q.transpose() - sigma - paper).norm();
      CHECK(error < 2.0 * eps * eps * w_unit.norm() * w_unit.norm() * sigma.norm());
    }
  }
}

TEST_CASE("a spin about z alone takes the closed form of the same Cayley rotation", "[rotation]") {
  std::mt19937_64 rng(17);
  for (double size : {1e-8, 1e-3, 0.1, 2.0}) {
    const Mat3 w_any = test::random_skew(rng, size);
    Mat3 w = Mat3::Zero();  // the plane-strain spin of the SPH solver
    w(0, 1) = w_any(0, 1), w(1, 0) = -w_any(0, 1);
    State s;
    s.stress = test::random_symmetric(rng, 1e5);
    const Mat3 Q = spin_rotation(w);
    const State r = rotate_state(s, w);
    CHECK((r.stress - Q * s.stress * Q.transpose()).norm() < 1e-14 * s.stress.norm());
    CHECK(r.stress(2, 2) == s.stress(2, 2));
    // The closed form on a tensor that is not symmetric rotates it the same way.
    Mat3 a = test::random_symmetric(rng, 1e-2);
    a(0, 2) += 1e-3, a(2, 1) -= 2e-3;
    const double half = 0.5 * w(0, 1), c = (1.0 - half * half) / (1.0 + half * half),
                 sn = 2.0 * half / (1.0 + half * half);
    CHECK((rotate_about_z(a, c, sn) - Q * a * Q.transpose()).norm() < 1e-14 * a.norm());
  }
}

TEST_CASE("a spin about any axis turns the state's stress by the paper's terms, with the spin", "[rotation]") {
  // rotate_state's general path (a spin not about z alone): to first order the stress changes by
  // σωᵀ + ωσ (eq 21/28), not by its negative (a rotation against the spin).
  std::mt19937_64 rng(23);
  State s;
  s.stress = test::random_symmetric(rng, 1e5);
  const Mat3 w_unit = test::random_skew(rng, 1.0);
  REQUIRE(w_unit(0, 2) != 0.0);  // the general path
  for (double eps : {1e-2, 1e-3}) {
    const Mat3 w = eps * w_unit;
    const Mat3 paper = s.stress * w.transpose() + w * s.stress;
    const double error = (rotate_state(s, w).stress - s.stress - paper).norm();
    CHECK(error < 2.0 * eps * eps * w_unit.norm() * w_unit.norm() * s.stress.norm());
    CHECK(error < 0.1 * paper.norm());
  }
}
