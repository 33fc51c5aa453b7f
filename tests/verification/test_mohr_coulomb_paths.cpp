// Mohr–Coulomb on triaxial compression and extension, drained and undrained: every integrator and
// the CVODE reference against the closed forms (verification/closed_form/mohr_coulomb_triaxial.h),
// and the closed forms' peak against the Coulomb strength written out here.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "verification/closed_form/closed_form.h"
#include "verification/closed_form/mohr_coulomb_triaxial.h"
#include "verification/report/curve_errors.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
constexpr double kPhi = 35.0, kPsi = 10.0, kCohesion = 5e3;

MohrCoulomb model() {
  MohrCoulomb::Params p;
  p.density = 2000.0, p.young_modulus = 1e6, p.poisson_ratio = 0.3, p.friction_angle = kPhi;
  p.cohesion = kCohesion, p.dilatancy_angle = kPsi;
  return MohrCoulomb(p);
}
double sind(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }
double cosd(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

PointTest triaxial(LoadPath path, double target) {
  PointTest t;
  t.path = path;
  t.p_initial = 100e3;
  t.strain_targets = {target};
  t.increments = 50;
  return t;
}
}  // namespace

TEST_CASE("Mohr-Coulomb: the drained triaxial peak is 2(c cos phi + s_r sin phi)/(1 -/+ sin phi)",
          "[mohr-coulomb][closed-form]") {
  const MohrCoulomb mc = model();
  const double s = sind(kPhi), radial = 100e3, strength = 2.0 * (kCohesion * cosd(kPhi) + radial * s);
  const MohrCoulombTriaxial drained(mc, radial, false);
  CHECK(drained.yield_q(+1) == Approx(strength / (1.0 - s)));
  CHECK(drained.yield_q(-1) == Approx(strength / (1.0 + s)));
  for (const char* integrator : {"explicit", "substep", "implicit", "cvode"}) {
    INFO(integrator);
    const PointCurve compression = run_point_test(mc, triaxial(LoadPath::TriaxialDrained, 0.6), integrator);
    CHECK(compression.back().q == Approx(strength / (1.0 - s)).epsilon(1e-9));
    CHECK(compression.back().sig_r == Approx(radial).epsilon(1e-9));
    const PointCurve extension = run_point_test(mc, triaxial(LoadPath::TriaxialDrained, -0.2), integrator);
    CHECK(extension.back().q == Approx(-strength / (1.0 + s)).epsilon(1e-9));
  }
}

TEST_CASE("Mohr-Coulomb: every integrator and CVODE follow the closed forms in compression and extension",
          "[mohr-coulomb][closed-form][cvode]") {
  const Material mc = model();
  struct Case {
    LoadPath path;
    double target;
    const char* closed_form;
  };
  for (const Case& c : {Case{LoadPath::TriaxialDrained, 0.6, "mc-triaxial-drained"},
                        Case{LoadPath::TriaxialDrained, -0.2, "mc-triaxial-drained"},
                        Case{LoadPath::TriaxialUndrained, 0.5, "mc-triaxial-undrained"},
                        Case{LoadPath::TriaxialUndrained, -0.3, "mc-triaxial-undrained"}}) {
    const PointTest test = triaxial(c.path, c.target);
    const PointCurve reference = run_point_test(mc, test, "cvode");
    for (const char* integrator : {"explicit", "substep", "implicit", "cvode"}) {
      INFO(load_path_name(c.path) << " to eps_a = " << c.target << ", " << integrator);
      const PointCurve curve = integrator == std::string("cvode") ? reference : run_point_test(mc, test, integrator);
      std::vector<double> driven;
      for (const PointRecord& row : curve) driven.push_back(row.eps_a);
      CHECK(curve_errors(curve, closed_form_curve(c.closed_form, mc, test, driven), c.path).max() < 1e-8);
      CHECK(curve_errors(curve, as_reference(reference), c.path).max() < 1e-8);
    }
  }
}

TEST_CASE("Mohr-Coulomb: undrained, p' climbs the failure line with psi > 0 and stays with psi = 0",
          "[mohr-coulomb][closed-form]") {
  const MohrCoulomb dilatant = model();
  const MohrCoulombTriaxial cf(dilatant, 100e3, true);
  const double s = sind(kPhi), cc = kCohesion * cosd(kPhi);
  for (double eps_a : {0.3, 0.5, -0.2, -0.4}) {
    const ReferencePoint r = cf.at(eps_a);
    // On the failure line: σ'_r = p' − q/3 and |q| = 2(c cosφ + σ'_r s)/(1 ∓ s) (drained form, any σ'_r).
    const double radial = r.p - r.q / 3.0;
    const double sign = eps_a > 0 ? 1.0 : -1.0;
    CHECK(std::abs(r.q) == Approx(2.0 * (cc + radial * s) / (1.0 - sign * s)));
    CHECK(r.p > 100e3);
  }
  MohrCoulomb::Params params = dilatant.params();
  params.dilatancy_angle = 0.0;
  const MohrCoulombTriaxial plain(MohrCoulomb(params), 100e3, true);
  CHECK(plain.at(0.5).p == 100e3);
  CHECK(plain.at(0.5).q == Approx(plain.yield_q(+1)));
}
