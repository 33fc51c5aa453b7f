// The CVODE reference in the corners of the Mohr–Coulomb pyramid and its tension cut-off: strain
// paths into the pyramid's apex, onto a cut-off plane, its edge and its apex, against `implicit`,
// whose principal-stress return is exact for this piecewise-linear model (every plane's return in
// closed form, the apex's too).
#include <catch2/catch.hpp>

#include <cmath>

#include "verification/programme/programme.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {

MohrCoulomb::Params mohr_coulomb(double phi, double c, double psi, double tension_cutoff) {
  MohrCoulomb::Params p{};
  p.density = 2000.0;
  p.young_modulus = 1e7;
  p.poisson_ratio = 0.25;
  p.friction_angle = phi;
  p.cohesion = c;
  p.dilatancy_angle = psi;
  p.tension_cutoff = tension_cutoff;
  p.integrator = Integrator::Implicit;
  return p;
}

/// From p' = p0 (isotropic), the strain `total` (tension-positive principal strains, every
/// component imposed) in `increments` increments.
Programme strain_path(double p0, const Vec6& total, int increments) {
  Programme programme;
  programme.initial.stress = isotropic_stress(p0);
  Leg leg;
  leg.increment = total / increments;
  leg.increments = increments;
  programme.legs = {leg};
  programme.leg_names = {"leg 1"};
  return programme;
}

/// Largest stress difference between CVODE and implicit over the rows, relative to `scale`, and
/// the last CVODE row.
PointRecord check_against_implicit(const Material& material, const Programme& programme, double scale) {
  const PointCurve reference = run_programme(material, programme, "cvode");
  const PointCurve implicit = run_programme(material, programme, "implicit");
  REQUIRE(reference.size() == implicit.size());
  double difference = 0.0;
  for (std::size_t k = 0; k < reference.size(); ++k)
    for (auto column : {&PointRecord::sig_a, &PointRecord::sig_r, &PointRecord::p, &PointRecord::q})
      difference = std::max(difference, std::abs(reference[k].*column - implicit[k].*column));
  INFO("largest stress difference " << difference << " Pa");
  CHECK(difference <= 1e-6 * scale);
  return reference.back();
}

}  // namespace

TEST_CASE("cvode reaches the Mohr-Coulomb apex (no cut-off) as implicit does", "[cvode][corners]") {
  // φ = 35°, c = 10 Pa, ψ = 20°, ν = 0.25: the apex c cotφ = 14.3 Pa (tension).
  const MohrCoulomb mc(mohr_coulomb(35.0, 10.0, 20.0, MohrCoulomb::Params::kNoTensionCutoff));
  const double apex = mc.apex_stress();
  SECTION("isotropic extension") {
    const PointRecord end =
        check_against_implicit(mc, strain_path(100e3, Vec6(0.01, 0.01, 0.01, 0, 0, 0), 20), 100e3);
    CHECK(-end.p == Approx(apex).epsilon(1e-9));
    CHECK(end.q == Approx(0.0).margin(1e-9 * 100e3));
  }
  SECTION("unequal extension, along a plane and an edge into the apex") {
    const PointRecord end =
        check_against_implicit(mc, strain_path(100e3, Vec6(0.03, 0.01, 0.005, 0, 0, 0), 20), 100e3);
    CHECK(-end.p == Approx(apex).epsilon(1e-9));
  }
}

TEST_CASE("cvode reaches the tension cut-off's plane, edge and apex as implicit does", "[cvode][corners]") {
  // c = 100 kPa, φ = 30°: the pyramid's apex at c cotφ = 173 kPa, far beyond T = 1 kPa, so the
  // cut-off is reached first from p' = 10 kPa.
  constexpr double kT = 1e3;
  const MohrCoulomb mc(mohr_coulomb(30.0, 100e3, 10.0, kT));
  SECTION("a plane: uniaxial extension") {
    const PointRecord end =
        check_against_implicit(mc, strain_path(10e3, Vec6(0.01, 0, 0, 0, 0, 0), 20), 10e3);
    CHECK(-end.sig_a == Approx(kT).epsilon(1e-9));
  }
  SECTION("an edge: equal biaxial extension") {
    const PointRecord end =
        check_against_implicit(mc, strain_path(10e3, Vec6(0.01, 0.01, 0, 0, 0, 0), 20), 10e3);
    CHECK(-end.sig_a == Approx(kT).epsilon(1e-9));  // σ_xx (σ_yy with it: the rows agree with implicit)
  }
  SECTION("the apex: isotropic extension") {
    const PointRecord end =
        check_against_implicit(mc, strain_path(10e3, Vec6(0.01, 0.01, 0.01, 0, 0, 0), 20), 10e3);
    CHECK(-end.p == Approx(kT).epsilon(1e-9));
    CHECK(end.q == Approx(0.0).margin(1e-9 * 10e3));
  }
}
