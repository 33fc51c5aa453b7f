// Mohr–Coulomb at one point: the yield function on its meridians, its gradients, the principal-stress
// return (plane, edges, apex, cut-off) and its consistent tangent. Expected values from the formulas
// of constitutive/models/mohr_coulomb.h derived independently here, or from central differences.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "constitutive/integrators/implicit_mohr_coulomb.h"
#include "constitutive/tangent.h"
#include "helpers.h"

using namespace soilsph;
using Kind = MohrCoulombReturn::Kind;

namespace {
constexpr double kPhi = 30.0, kPsi = 10.0, kCohesion = 10e3;

MohrCoulomb::Params params(double tension_cutoff = MohrCoulomb::Params::kNoTensionCutoff) {
  MohrCoulomb::Params p;
  p.density = 2000.0, p.young_modulus = 10e6, p.poisson_ratio = 0.25, p.friction_angle = kPhi;
  p.cohesion = kCohesion, p.dilatancy_angle = kPsi, p.tension_cutoff = tension_cutoff;
  return p;
}
double sind(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }
double cosd(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

/// A fixed rotation, so that principal directions are not the axes.
Mat3 rotated(const Vec3& principal) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  return R * principal.asDiagonal() * R.transpose();
}
}  // namespace

TEST_CASE("Mohr-Coulomb: the yield function vanishes on the compression and extension meridians",
          "[mohr-coulomb]") {
  const MohrCoulomb mc(params());
  const double s = sind(kPhi), cc = kCohesion * cosd(kPhi);
  for (double radial : {10e3, 100e3, 1e6}) {  // compression-positive radial stress
    // Compression meridian: σ'_a = σ'_1 > σ'_r; tension-positive σ1 = σ2 = −σ'_r, σ3 = −σ'_a.
    const double axial_compression = (2.0 * cc + radial * (1.0 + s)) / (1.0 - s);
    const Mat3 compression = rotated(Vec3(-radial, -radial, -axial_compression));
    CHECK(mc.yield(compression) == Approx(0.0).margin(1e-9 * axial_compression));
    // 2(c cosφ + σ'_r sinφ)/(1 − sinφ), the drained triaxial peak.
    CHECK(axial_compression - radial == Approx(2.0 * (cc + radial * s) / (1.0 - s)));
    // Extension meridian: σ'_a = σ'_3 < σ'_r.
    const double axial_extension = (radial * (1.0 - s) - 2.0 * cc) / (1.0 + s);
    const Mat3 extension = rotated(Vec3(-axial_extension, -radial, -radial));
    CHECK(mc.yield(extension) == Approx(0.0).margin(1e-9 * radial));
    // Inside and outside.
    CHECK(mc.yield(rotated(Vec3(-radial, -radial, -0.99 * axial_compression))) < 0.0);
    CHECK(mc.yield(rotated(Vec3(-radial, -radial, -1.01 * axial_compression))) > 0.0);
  }
  // The apex: c cotφ in isotropic tension.
  CHECK(mc.apex_stress() == Approx(kCohesion * cosd(kPhi) / sind(kPhi)));
  CHECK(mc.yield(mc.apex_stress() * Mat3::Identity()) == Approx(0.0).margin(1e-9));
}

TEST_CASE("Mohr-Coulomb: gradients equal central differences off the edges", "[mohr-coulomb]") {
  const MohrCoulomb mc(params());
  const Mat3 sigma = rotated(Vec3(-20e3, -50e3, -140e3));
  const double h = 1.0;  // Pa
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      Mat3 d = Mat3::Zero();
      d(i, j) = d(j, i) = h;
      const double scale = i == j ? 1.0 : 2.0;  // a shear perturbation moves both entries
      CHECK((mc.yield(sigma + d) - mc.yield(sigma - d)) / (2.0 * h) ==
            Approx(scale * mc.yield_gradient(sigma)(i, j)).margin(1e-8));
    }
  // The flow direction: the same with ψ, so its trace is the plastic dilation 2 sinψ per unit Δγ.
  CHECK(mc.flow_direction(sigma).trace() == Approx(2.0 * sind(kPsi)));
  CHECK(mc.yield_gradient(sigma).trace() == Approx(2.0 * sind(kPhi)));
  // At an edge the gradient is the mean of the two planes' and does not depend on the eigenvectors.
  const Mat3 edge = rotated(Vec3(-50e3, -50e3, -200e3));
  const Mat3 n = mc.yield_gradient(edge);
  CHECK(n.trace() == Approx(2.0 * sind(kPhi)));
  CHECK((n - n.transpose()).norm() < 1e-12);
}

TEST_CASE("Mohr-Coulomb: the return lands on the plane, the edges, the apex or the cut-off", "[mohr-coulomb]") {
  const MohrCoulomb mc(params());
  const Moduli D = mc.elasticity().at(0.0);
  const double s = sind(kPhi), t = sind(kPsi);
  SECTION("main plane: dgamma = f_tr / (4G(1 + sin phi sin psi/3) + 4K sin phi sin psi) (de Souza Neto Box 8.5)") {
    const Vec3 trial(-40e3, -90e3, -300e3);
    const double f_trial = (trial(0) - trial(2)) + (trial(0) + trial(2)) * s - mc.cohesion_term();
    REQUIRE(f_trial > 0.0);
    const MohrCoulombReturn r = return_principal(mc, trial, D);
    CHECK(r.kind == Kind::Plane);
    CHECK(r.multiplier == Approx(f_trial / (4.0 * D.G * (1.0 + s * t / 3.0) + 4.0 * D.K * s * t)));
    CHECK(mc.yield(r.stress.asDiagonal().toDenseMatrix()) == Approx(0.0).margin(1e-6));
    CHECK(r.stress(1) == Approx(trial(1) + (4.0 * D.G / 3.0 - 2.0 * D.K) * t * r.multiplier));
  }
  SECTION("triaxial compression trial: the right edge σ1 = σ2") {
    const MohrCoulombReturn r = return_principal(mc, Vec3(-50e3, -50e3, -400e3), D);
    CHECK(r.kind == Kind::RightEdge);
    CHECK(r.stress(0) == r.stress(1));
    CHECK(mc.yield(r.stress.asDiagonal().toDenseMatrix()) == Approx(0.0).margin(1e-6));
  }
  SECTION("triaxial extension trial: the left edge σ2 = σ3") {
    const MohrCoulombReturn r = return_principal(mc, Vec3(0.0, -150e3, -150e3), D);
    CHECK(r.kind == Kind::LeftEdge);
    CHECK(r.stress(1) == r.stress(2));
    CHECK(mc.yield(r.stress.asDiagonal().toDenseMatrix()) == Approx(0.0).margin(1e-6));
  }
  SECTION("isotropic tension beyond the apex: the apex c cotφ") {
    const Vec3 trial = Vec3::Constant(2.0 * mc.apex_stress()) + Vec3(1e3, 0.0, -1e3);
    const MohrCoulombReturn r = return_principal(mc, trial, D);
    CHECK(r.kind == Kind::Apex);
    CHECK(r.stress == Vec3::Constant(mc.apex_stress()));
    const State next = implicit_update(mc, State{}, (trial / (3.0 * D.K)).asDiagonal().toDenseMatrix());
    CHECK(second_deviatoric_invariant(next.stress) == 0.0);
    CHECK(next.plastic_multiplier > 0.0);
  }
  SECTION("a tension cut-off T: the largest principal stress returns to T") {
    const MohrCoulomb cut(params(2e3));
    const MohrCoulombReturn r = return_principal(cut, Vec3(8e3, -20e3, -30e3), D);
    CHECK(r.kind == Kind::Cutoff);
    CHECK(r.stress(0) == Approx(2e3));
    CHECK(cut.yield(r.stress.asDiagonal().toDenseMatrix()) <= 1e-6);
    const MohrCoulombReturn corner = return_principal(cut, Vec3::Constant(10e3), D);
    CHECK(corner.stress == Vec3::Constant(2e3));
  }
  SECTION("where the compression edge meets the cut-off: sigma1 = sigma2 = T on the pyramid") {
    // Four planes meet at P = (T, T, σ3) with (1 + sinφ) T − (1 − sinφ) σ3 = 2c cosφ: the pyramid's
    // two with σ3 and the cut-offs of σ1 and σ2. A trial P + D(λ0 g0 + λ1 g1 + λ3 e1 + λ4 e2) with
    // λ ≥ 0 and their flow directions g0 = (1+sinψ, 0, −(1−sinψ)), g1 = (0, 1+sinψ, −(1−sinψ))
    // returns to P (its conditions hold by construction). Triaxial compression at low confinement
    // ends there; before the corner's four triples were sets, such trials fell to the cut-off's apex.
    const double T = 0.0;
    const MohrCoulomb cut(params(T));
    const Vec3 P(T, T, ((1.0 + s) * T - 2.0 * kCohesion * cosd(kPhi)) / (1.0 - s));
    const Vec3 g0(1.0 + t, 0.0, -(1.0 - t)), g1(0.0, 1.0 + t, -(1.0 - t));
    const Mat3 Dp = (D.K - 2.0 * D.G / 3.0) * Mat3::Ones() + 2.0 * D.G * Mat3::Identity();
    using Weights = Eigen::Vector4d;  // λ0, λ1, λ3, λ4
    for (const Weights& weights :
         {Weights(1e-3, 1e-3, 1e-3, 1e-3), Weights(0.0, 1e-3, 2e-3, 0.0), Weights(1e-3, 0.0, 0.0, 1e-3),
          Weights(2e-3, 1e-3, 1e-3, 0.0), Weights(0.0, 0.0, 1e-3, 1e-3)}) {
      const Vec3 trial = P + Dp * (weights(0) * g0 + weights(1) * g1 + weights(2) * Vec3::UnitX() +
                                   weights(3) * Vec3::UnitY());
      INFO("weights " << weights.transpose() << ", trial " << trial.transpose());
      REQUIRE(trial(0) >= trial(1));
      REQUIRE(trial(1) >= trial(2));
      const MohrCoulombReturn r = return_principal(cut, trial, D);
      CHECK(r.kind == Kind::Cutoff);
      CHECK(r.stress(0) == T);
      CHECK(r.stress(1) == T);
      CHECK(r.stress(2) == Approx(P(2)));
    }
  }
}

TEST_CASE("Mohr-Coulomb: the implicit update's consistent tangent equals central differences",
          "[mohr-coulomb][tangent]") {
  MohrCoulomb::Params p = params();
  p.integrator = Integrator::Implicit;
  const MohrCoulomb mc(p);
  State start;
  start.stress = rotated(Vec3(-60e3, -80e3, -100e3));
  // One increment onto the main plane, one onto the compression edge, one elastic.
  const Mat3 shear = rotated(Vec3(2e-3, 0.5e-3, -4e-3));
  const Mat3 triaxial = Vec3(1e-3, 1e-3, -6e-3).asDiagonal();
  for (const Mat3& increment : {shear, triaxial, Mat3(1e-5 * shear)}) {
    const Mat6 analytic = mc.consistent_tangent(start, increment);
    const Mat6 numeric = finite_difference_tangent(mc, start, increment);
    CHECK((analytic - numeric).norm() <= 1e-5 * numeric.norm());
  }
  // From an isotropic state a triaxial trial has two equal principal stresses: the edge return,
  // where the eigenvector spin term takes its limit.
  State isotropic;
  isotropic.stress = isotropic_stress(100e3);
  const Moduli D = mc.elasticity().at(0.0);
  const Mat3 loading = Vec3(1e-2, 1e-2, -2e-2).asDiagonal();  // isochoric: f_tr > 0
  const Vec3 trial = Vec3::Constant(-100e3) + D.K * loading.trace() * Vec3::Ones() +
                     2.0 * D.G * deviator(loading).diagonal();
  REQUIRE(return_principal(mc, principal(trial.asDiagonal().toDenseMatrix()).values, D).kind == Kind::RightEdge);
  const Mat6 analytic = mc.consistent_tangent(isotropic, loading);
  const Mat6 numeric = finite_difference_tangent(mc, isotropic, loading);
  CHECK((analytic - numeric).norm() <= 1e-5 * numeric.norm());
}
