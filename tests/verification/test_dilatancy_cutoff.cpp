// The dilatancy cut-off (constitutive/models/dilatancy_cutoff.h) at a material point, D-P and MC, every
// integrator and the CVODE reference, against closed forms that follow from the cut-off's definition:
//  - drained triaxial compression: past the peak the soil dilates at the flow rule's ratio until its
//    plastic dilation is the cut-off, then shears at constant volume, so
//    ε_v(ε_a) = max(ε_v without cut-off (the closed forms of verification/), ε_v at the peak − cut-off)
//    past the peak;
//  - undrained (ε_v = 0): the plastic dilation is held back elastically, Δp' = K ε_v^p, so p' rises
//    with ψ > 0 until p' = p_i + K · cut-off and then stays, q on the failure line there.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "closed_form_fixtures.h"
#include "verification/closed_form/drucker_prager_triaxial.h"
#include "verification/closed_form/mohr_coulomb_triaxial.h"
#include "verification/point_test.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
constexpr double kCutoff = 0.01;
constexpr double kPInitial = 100e3;
const char* const kSchemes[] = {"explicit", "substep", "implicit", "cvode"};

DruckerPrager drucker_prager(double cutoff) {
  DruckerPrager::Params p = test::table1_drucker_prager_params(0.0, 20.0);
  p.dilatancy_cutoff = cutoff;
  return DruckerPrager(p);
}

/// E = 10 MPa drained (its peak at ε_a = 2.9 %, 1 MPa's at 29 %), 1 MPa undrained (the stiffer soil's
/// undrained path takes `substep` and the driver out of their depth: docs/validation/known-limits.md).
MohrCoulomb mohr_coulomb(double cutoff, double young_modulus) {
  MohrCoulomb::Params p;
  p.density = 2000.0, p.young_modulus = young_modulus, p.poisson_ratio = 0.3, p.friction_angle = 35.0;
  p.cohesion = 5e3, p.dilatancy_angle = 10.0, p.dilatancy_cutoff = cutoff;
  return MohrCoulomb(p);
}

PointTest triaxial(LoadPath path, double target, int increments) {
  PointTest t;
  t.path = path;
  t.p_initial = kPInitial;
  t.strain_targets = {target};
  t.increments = increments;
  return t;
}

/// The integrators' bound, and CVODE's (its case tolerance against closed forms, as elsewhere).
double tolerance(const std::string& integrator) { return integrator == "cvode" ? 1e-6 : 1e-9; }

/// The drained curve against the closed form with the cut-off; `peak_strain` from the closed form.
template <class ClosedForm>
void check_drained(const Material& model, const ClosedForm& without_cutoff, double peak_strain) {
  const double floor = without_cutoff.at(peak_strain).eps_v - kCutoff;
  for (const std::string integrator : kSchemes) {
    const PointCurve curve = run_point_test(model, triaxial(LoadPath::TriaxialDrained, 0.3, 100), integrator);
    double worst = 0.0;
    for (const PointRecord& r : curve) {
      const double free = without_cutoff.at(r.eps_a).eps_v;
      worst = std::max(worst, std::abs(r.eps_v - (r.eps_a <= peak_strain ? free : std::max(free, floor))));
    }
    INFO(integrator << ": largest |eps_v - closed form| " << worst << ", final eps_v " << curve.back().eps_v
                    << " against " << floor);
    CHECK(worst <= tolerance(integrator));
    // The cut-off is reached inside the test: without it the soil would have dilated further.
    CHECK(without_cutoff.at(0.3).eps_v < floor - 10.0 * kCutoff);
  }
}

template <class Model>
void check_undrained(const Model& model) {
  const double K = model.elasticity().at(0.0).K;
  const double p_final = kPInitial + K * kCutoff;
  const FailureLine line = model.triaxial_failure_line();
  for (const std::string integrator : kSchemes) {
    const PointCurve curve =
        run_point_test(Material(model), triaxial(LoadPath::TriaxialUndrained, 0.3, 100), integrator);
    INFO(integrator << ": final p' " << curve.back().p << " against " << p_final << ", q " << curve.back().q);
    CHECK(curve.back().p == Approx(p_final).epsilon(tolerance(integrator)));
    CHECK(curve.back().q == Approx(line.slope * p_final + line.intercept).epsilon(tolerance(integrator)));
    // The cut-off ended the growth of p' before the end of the test: it is flat over the last tenth.
    CHECK(curve[curve.size() - 11].p == Approx(p_final).epsilon(tolerance(integrator)));
  }
}
}  // namespace

TEST_CASE("dilatancy cut-off, drained triaxial: the soil stops dilating at the cut-off, every scheme and CVODE",
          "[dilatancy][cutoff][cvode]") {
  SECTION("Drucker-Prager, psi = 20 degrees") {
    const DruckerPrager dp = drucker_prager(kCutoff);
    const DruckerPragerDrainedTriaxial without(drucker_prager(std::numeric_limits<double>::infinity()), kPInitial);
    check_drained(dp, without, without.yield_strain());
  }
  SECTION("Mohr-Coulomb, psi = 10 degrees, c = 5 kPa") {
    const MohrCoulomb mc = mohr_coulomb(kCutoff, 10e6);
    const MohrCoulombTriaxial without(mohr_coulomb(std::numeric_limits<double>::infinity(), 10e6), kPInitial, false);
    check_drained(mc, without, without.yield_strain(+1));
  }
}

TEST_CASE("dilatancy cut-off, undrained triaxial: p' stops at p_i + K * cutoff, every scheme and CVODE",
          "[dilatancy][cutoff][cvode]") {
  SECTION("Drucker-Prager") { check_undrained(drucker_prager(kCutoff)); }
  SECTION("Mohr-Coulomb") { check_undrained(mohr_coulomb(kCutoff, 1e6)); }
}

TEST_CASE("dilatancy cut-off: an increment that crosses it is split there, and psi = 0 needs no twin",
          "[dilatancy][cutoff]") {
  const DruckerPrager dp = drucker_prager(kCutoff);
  REQUIRE(dp.limits_dilation());
  CHECK(dp.non_dilating().alpha_psi() == 0.0);
  CHECK(&dp.flowing_at(0.5 * kCutoff) == &dp);
  CHECK(&dp.flowing_at(kCutoff) == &dp.non_dilating());
  // On the cone at p = 100 kPa, one large shear increment whose flow would dilate by ~0.03.
  State start;
  const double p = kPInitial, q = dp.triaxial_failure_line().slope * p;  // c = 0
  start.stress = Mat3::Identity() * -p;
  start.stress(0, 0) -= 2.0 * q / 3.0, start.stress(1, 1) += q / 3.0, start.stress(2, 2) += q / 3.0;
  REQUIRE(std::abs(dp.normalized_yield(start.stress)) < 1e-12);
  Mat3 shear = Mat3::Zero();
  shear(0, 0) = -0.2, shear(1, 1) = 0.1, shear(2, 2) = 0.1;
  const State free = drucker_prager(std::numeric_limits<double>::infinity()).update(start, shear, Mat3::Zero());
  const double K = dp.elasticity().at(0.0).K;
  const double free_dilation = shear.trace() - (free.stress.trace() - start.stress.trace()) / (3.0 * K);
  REQUIRE(free_dilation > 2.0 * kCutoff);
  for (Integrator integrator : soilsph::kIntegrators) {
    DruckerPrager::Params params = dp.params();
    params.integrator = integrator;
    const DruckerPrager model(params);
    const State end = model.update(start, shear, Mat3::Zero());
    INFO(integrator_name(integrator) << ": plastic dilation " << end.plastic_dilation);
    CHECK(end.plastic_dilation == Approx(kCutoff).epsilon(1e-9));
    CHECK(model.normalized_yield(end.stress) <= 1e-9);
    // Past the cut-off the flow is isochoric: the next increment adds no plastic volume.
    const State next = model.update(end, 0.1 * shear, Mat3::Zero());
    CHECK(next.plastic_dilation == Approx(kCutoff).epsilon(1e-9));
  }
  DruckerPrager::Params no_dilatancy = dp.params();
  no_dilatancy.dilatancy_angle = 0.0;
  CHECK_FALSE(DruckerPrager(no_dilatancy).limits_dilation());
}
