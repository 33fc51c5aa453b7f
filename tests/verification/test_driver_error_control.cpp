// The driver's error control (verification/driver/path_substeps.h) on a leg whose every stress
// component is imposed: Peric's drained triaxial stress path of Modified Cam-Clay towards the
// critical state, against its closed form (verification/closed_form/cam_clay_drained.h).
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "verification/closed_form/cam_clay_drained.h"
#include "verification/programme/programme.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {

/// The clay of Peric (2006) as OpenGeoSys's ModCamClay tests give it (λ = 0.077, κ = 0.0066,
/// M = 1.2, i.e. φ = 30° by eq 26, v0 = 1.788, ν = 0.3), with K = (1+e0) p/κ.
ModifiedCamClay peric_clay(Integrator integrator) {
  ModifiedCamClay::Params p{};
  p.density = 2000.0;
  p.poisson_ratio = 0.3;
  p.friction_angle = 30.0;
  p.compression_index = 0.077;
  p.swelling_index = 0.0066;
  p.initial_void_ratio = 0.788;
  p.elasticity = Elasticity::Kind::PressureDependent;
  p.integrator = integrator;
  return ModifiedCamClay(p);
}

constexpr double kP0 = 200e3;
constexpr double kFractionOfFailure = 0.98;

/// Normally consolidated at p' = 200 kPa, σ_r held, σ_a raised until q = 0.98 q_f in `increments`
/// equal stress increments: every stress component imposed (shear strains held at 0).
Programme peric_path(const ModifiedCamClay& clay, int increments, double path_tolerance) {
  const CamClayDrainedTriaxial closed(clay, kP0, 1.0);
  Programme programme;
  programme.initial.stress = isotropic_stress(kP0);
  programme.initial.pc = kP0;
  Leg leg;
  leg.stress_imposed = {true, true, true, false, false, false};
  leg.increment(0) = -kFractionOfFailure * closed.failure_q() / increments;  // tension-positive σ_a
  leg.increments = increments;
  programme.legs = {leg};
  programme.leg_names = {"drained stress path"};
  programme.path_tolerance = path_tolerance;
  return programme;
}

/// Largest |ε_q − ε_q,closed form| over the rows of the curve, ε_q = ε_a − ε_v/3 at each row's q.
double shear_strain_error(const ModifiedCamClay& clay, const PointCurve& curve) {
  const CamClayDrainedTriaxial closed(clay, kP0, 1.0);
  double error = 0.0;
  for (const PointRecord& r : curve) {
    const double expected = closed.axial_strain_at(r.q) - closed.volumetric_strain_at(r.q) / 3.0;
    error = std::max(error, std::abs(r.eps_q - expected));
  }
  return error;
}

}  // namespace

TEST_CASE(
    "Peric's drained stress path at 20 increments: path_tolerance 1e-4 brings eps_q within 1e-3 of "
    "the closed form",
    "[path-substeps][closed-form]") {
  for (Integrator integrator : {Integrator::Implicit, Integrator::Substep}) {
    const ModifiedCamClay clay = peric_clay(integrator);
    const Material material = clay;
    const char* name = integrator == Integrator::Implicit ? "implicit" : "substep";
    INFO(name);
    const double uniform = shear_strain_error(clay, run_programme(material, peric_path(clay, 20, 0.0), name));
    const double controlled =
        shear_strain_error(clay, run_programme(material, peric_path(clay, 20, 1e-4), name));
    INFO("eps_q error: uniform increments " << uniform << ", path_tolerance 1e-4 " << controlled);
    CHECK(uniform > 1e-2);  // the error the control exists for
    CHECK(controlled <= 1e-3);
  }
}

TEST_CASE("Peric's drained stress path: the eps_q error falls with path_tolerance",
          "[path-substeps][closed-form]") {
  const ModifiedCamClay clay = peric_clay(Integrator::Implicit);
  const Material material = clay;
  const double loose =
      shear_strain_error(clay, run_programme(material, peric_path(clay, 20, 1e-3), "implicit"));
  const double tight =
      shear_strain_error(clay, run_programme(material, peric_path(clay, 20, 1e-5), "implicit"));
  INFO("path_tolerance 1e-3: " << loose << ", 1e-5: " << tight);
  CHECK(tight < 0.3 * loose);
}

TEST_CASE(
    "Peric's drained stress path: eps_q error and cost, uniform increments against path_tolerance "
    "(printed, not checked)",
    "[.cost]") {
  const auto time_of = [](const auto& run) {
    constexpr int kRepeats = 5;
    std::vector<double> seconds;
    for (int r = 0; r < kRepeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      run();
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(seconds.begin(), seconds.end());
    return seconds[kRepeats / 2];
  };
  for (Integrator integrator : {Integrator::Implicit, Integrator::Substep}) {
    const ModifiedCamClay clay = peric_clay(integrator);
    const Material material = clay;
    const char* name = integrator == Integrator::Implicit ? "implicit" : "substep";
    // The times against the uniform 20-increment run of the same integrator, in this process: on a
    // loaded machine the ratio is the number to compare.
    double reference_seconds = 0.0;
    const auto row = [&](int increments, double tolerance) {
      const Programme programme = peric_path(clay, increments, tolerance);
      PointCurve curve;
      const double seconds = time_of([&] { curve = run_programme(material, programme, name); });
      if (reference_seconds == 0.0) reference_seconds = seconds;
      std::printf("%-8s %5d increments, path_tolerance %-6g: eps_q error %.2e, %.2f ms, %.1f x uniform 20\n",
                  name, increments, tolerance, shear_strain_error(clay, curve), 1e3 * seconds,
                  seconds / reference_seconds);
    };
    for (int increments : {20, 100, 1000, 10000}) row(increments, 0.0);
    for (double tolerance : {1e-3, 1e-4, 1e-5}) row(20, tolerance);
  }
}
