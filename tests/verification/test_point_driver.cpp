// The mixed-control driver: imposed stresses held, linear-elastic paths against Hooke's law.
#include <catch2/catch.hpp>

#include "materials.h"
#include "verification/point_test.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
PointTest drained_triaxial(double strain, int increments) {
  PointTest t;
  t.path = LoadPath::TriaxialDrained;
  t.strain_targets = {strain};
  t.increments = increments;
  return t;
}
}  // namespace

TEST_CASE("drained triaxial: the driver holds the radial stress to 1e-10 relative", "[driver]") {
  PointTest test = drained_triaxial(0.1, 100);
  test.strain_targets = {0.1, 0.05, 0.12};  // load, unload, reload
  const std::vector<Material> materials = {test::drucker_prager(), test::drucker_prager(5e3, 10.0),
                                           test::cam_clay(), test::cam_clay(Elasticity::Kind::Constant)};
  for (const Material& material : materials) {
    for (double ocr : {1.0, 4.0}) {
      test.ocr = ocr;
      const PointCurve curve = run_point_test(material, test, "explicit");
      REQUIRE(curve.size() == 301);
      for (const PointRecord& r : curve) REQUIRE(std::abs(r.sig_r - test.p_initial) <= 1e-10 * test.p_initial);
      // The test is not trivial: the model yielded and the axial stress moved.
      REQUIRE(curve[100].sig_a > 1.5 * test.p_initial);
    }
  }
}

TEST_CASE("linear elastic drained triaxial: q = E eps_a, eps_r = -nu eps_a", "[driver][elastic]") {
  const double E = 2.5e6, nu = 0.27;
  const PointCurve curve = run_point_test(test::linear_elastic(E, nu), drained_triaxial(0.02, 10), "explicit");
  REQUIRE(curve.size() == 11);
  for (const PointRecord& r : curve) {
    CHECK(r.q == Approx(E * r.eps_a).margin(1e-9 * E * 0.02));
    CHECK(r.eps_r == Approx(-nu * r.eps_a).margin(1e-12));
    CHECK(r.p == Approx(100e3 + E * r.eps_a / 3.0).epsilon(1e-12));
  }
  CHECK(curve.back().eps_a == Approx(0.02).epsilon(1e-14));
}

TEST_CASE("linear elastic oedometer: constrained modulus and K0 = nu/(1-nu)", "[driver][elastic]") {
  const double E = 2.5e6, nu = 0.27;
  PointTest test;
  test.path = LoadPath::Oedometer;
  test.strain_targets = {0.01};
  test.increments = 10;
  const PointCurve curve = run_point_test(test::linear_elastic(E, nu), test, "explicit");
  const double constrained = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  const double k0 = nu / (1 - nu);
  for (std::size_t k = 1; k < curve.size(); ++k) {
    const PointRecord& r = curve[k];
    CHECK((r.sig_a - 100e3) / r.eps_a == Approx(constrained).epsilon(1e-10));
    CHECK((r.sig_r - 100e3) / (r.sig_a - 100e3) == Approx(k0).epsilon(1e-10));
    CHECK(r.eps_r == 0.0);
  }
}
