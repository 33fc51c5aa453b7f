// A stress-controlled leg past the soil's strength (verification/driver/strength_limit.h): the run
// stops with one message that names the increment and the stress reached, and gives the curve up to
// there. Expected strengths from each model's triaxial failure line q_f = slope p' + intercept on the
// drained path p' = σ_r + q/3 (σ_r held): q_f = (slope σ_r + intercept) / (1 − slope/3).
#include <catch2/catch.hpp>

#include <string>

#include "tests/common/table1_materials.h"
#include "verification/programme/programme.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {

constexpr double kRadial = 100e3;

/// From p' = 100 kPa (OCR 1 for MCC), σ_a raised to `axial` (compression-positive, Pa) with σ_r
/// held, in `increments` equal stress increments.
Programme drained_stress_leg(const Material& material, double axial, int increments, double path_tolerance) {
  Programme programme;
  programme.initial.stress = isotropic_stress(kRadial);
  programme.initial.pc = initial_preconsolidation(material, programme.initial.stress, 1.0);
  Leg leg;
  leg.stress_imposed = {true, true, true, false, false, false};
  leg.increment(0) = -(axial - kRadial) / increments;
  leg.increments = increments;
  programme.legs = {leg};
  programme.leg_names = {"leg 1 (drained, sig_a to " + std::to_string(axial) + " Pa)"};
  programme.path_tolerance = path_tolerance;
  return programme;
}

double failure_q(const Material& material) {
  const FailureLine line = *triaxial_failure_line(material);
  return (line.slope * kRadial + line.intercept) / (1.0 - line.slope / 3.0);
}

void check_stops_at_strength(const Material& material, const char* integrator, double path_tolerance) {
  const double q_f = failure_q(material);
  constexpr int kIncrements = 20;
  const double axial = kRadial + 1.9 * q_f;  // beyond the strength, which falls inside increment 11
  const double step = (axial - kRadial) / kIncrements;
  try {
    run_programme(material, drained_stress_leg(material, axial, kIncrements, path_tolerance), integrator);
    FAIL("a leg beyond the strength ran to its end");
  } catch (const StrengthReachedError& e) {
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("at or beyond the soil's strength") != std::string::npos);
    CHECK(message.find("of leg 1 (drained") != std::string::npos);
    CHECK(message.find("more increments may help") == std::string::npos);
    // The curve up to the last completed increment: every row below the strength, the last within
    // one increment of it.
    REQUIRE(e.curve.size() >= 2);
    const PointRecord& last = e.curve.back();
    CHECK(last.q <= q_f * (1.0 + 1e-6));
    CHECK(last.q > q_f - step * (1.0 + 1e-9));
    CHECK(e.curve.size() == static_cast<std::size_t>(std::floor(q_f / step)) + 1);
  }
}

}  // namespace

TEST_CASE("A drained stress leg past the Drucker-Prager strength stops with the strength reached",
          "[strength-limit]") {
  auto params = test::table1_drucker_prager_params();
  params.friction_angle = 30.0;
  for (Integrator integrator : {Integrator::Implicit, Integrator::Explicit}) {
    params.integrator = integrator;
    const Material dp = DruckerPrager(params);
    for (double path_tolerance : {0.0, 1e-4}) {
      INFO(integrator_name(integrator) << ", path_tolerance " << path_tolerance);
      check_stops_at_strength(dp, std::string(integrator_name(integrator)).c_str(), path_tolerance);
    }
  }
}

TEST_CASE("A drained stress leg past the Mohr-Coulomb strength stops with the strength reached",
          "[strength-limit]") {
  MohrCoulomb::Params params{};
  params.density = 2000.0;
  params.young_modulus = 1.0e7;
  params.poisson_ratio = 0.3;
  params.friction_angle = 30.0;
  params.cohesion = 5e3;
  params.integrator = Integrator::Implicit;
  const Material mc = MohrCoulomb(params);
  for (double path_tolerance : {0.0, 1e-4}) {
    INFO("path_tolerance " << path_tolerance);
    check_stops_at_strength(mc, "implicit", path_tolerance);
  }
}

TEST_CASE("A drained stress leg past the critical state of Modified Cam-Clay stops with the strength reached",
          "[strength-limit]") {
  for (Integrator integrator : {Integrator::Implicit, Integrator::Substep}) {
    auto params = test::table1_cam_clay_params();
    params.integrator = integrator;
    const Material mcc = ModifiedCamClay(params);
    for (double path_tolerance : {0.0, 1e-4}) {
      INFO(integrator_name(integrator) << ", path_tolerance " << path_tolerance);
      check_stops_at_strength(mcc, std::string(integrator_name(integrator)).c_str(), path_tolerance);
    }
  }
}
