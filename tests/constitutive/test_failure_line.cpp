// The failure-line hook (constitutive/failure_line.h): on the triaxial-compression meridian the line
// q = slope p' + intercept must be where each model fails, checked through the model's own yield
// function and flow rule rather than the formula the hook evaluates.
#include <catch2/catch.hpp>

#include "../common/table1_materials.h"

using namespace soilsph;

namespace {
/// Triaxial compression at (p', q), compression-positive in, tension-positive out: σ_a = −(p' + 2q/3),
/// σ_r = −(p' − q/3).
Mat3 triaxial_compression(double p, double q) {
  return Vec3(-(p + 2.0 * q / 3.0), -(p - q / 3.0), -(p - q / 3.0)).asDiagonal();
}

MohrCoulomb mohr_coulomb() {
  MohrCoulomb::Params p;
  p.density = 2000.0, p.young_modulus = 10e6, p.poisson_ratio = 0.25, p.friction_angle = 30.0;
  p.cohesion = 10e3, p.dilatancy_angle = 10.0;
  return MohrCoulomb(p);
}

/// The line lies on the yield surface of a perfectly plastic model, and 1 % more q is outside it.
template <class Model>
void check_on_yield_surface(const Model& model) {
  const FailureLine line = model.triaxial_failure_line();
  for (double p : {10e3, 100e3, 1e6}) {
    const double q = line.slope * p + line.intercept;
    INFO(Model::kName << " at p' = " << p << " Pa, q = " << q << " Pa");
    CHECK(model.normalized_yield(triaxial_compression(p, q), 0.0) == Approx(0.0).margin(1e-12));
    CHECK(model.normalized_yield(triaxial_compression(p, 1.01 * q), 0.0) > 1e-4);
  }
}
}  // namespace

TEST_CASE("failure line: D-P and Mohr-Coulomb fail on it in triaxial compression", "[failure-line]") {
  check_on_yield_surface(test::table1_drucker_prager(5e3, 10.0));
  check_on_yield_surface(test::table1_drucker_prager(0.0, 0.0));
  check_on_yield_surface(mohr_coulomb());
}

TEST_CASE("failure line: MCC's is the critical-state line (on the surface, no plastic volume change)",
          "[failure-line]") {
  const ModifiedCamClay mcc = test::table1_cam_clay();
  const FailureLine line = mcc.triaxial_failure_line();
  CHECK(line.intercept == 0.0);
  for (double p : {10e3, 100e3, 1e6}) {
    const double pc = 2.0 * p;  // the critical state is the top of the ellipse, p' = p_c/2
    const Mat3 sigma = triaxial_compression(p, line.slope * p);
    INFO("p' = " << p << " Pa");
    CHECK(mcc.normalized_yield(sigma, pc) == Approx(0.0).margin(1e-12));
    const Mat3 n = mcc.flow_direction(sigma, pc);
    CHECK(std::abs(n.trace()) < 1e-12 * n.norm());
  }
}
