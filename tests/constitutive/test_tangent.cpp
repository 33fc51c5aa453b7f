// Voigt conversions and the finite-difference tangent against the elastic stiffness in closed form.
#include <catch2/catch.hpp>

#include "constitutive/tangent.h"
#include "helpers.h"

using namespace soilsph;

TEST_CASE("Voigt conversions round-trip and preserve the work product", "[tangent]") {
  std::mt19937_64 rng(1);
  const Mat3 s = test::random_symmetric(rng, 1.0), e = test::random_symmetric(rng, 1.0);
  CHECK((stress_from_voigt(stress_to_voigt(s)) - s).norm() < 1e-15);
  CHECK((strain_from_voigt(strain_to_voigt(e)) - e).norm() < 1e-15);
  CHECK(stress_to_voigt(s).dot(strain_to_voigt(e)) == Approx(ddot(s, e)));
}

TEST_CASE("the tangent of an elastic update is the isotropic stiffness matrix", "[tangent]") {
  const double E = 1.0e6, nu = 0.3;
  const LinearElastic model({2000.0, E, nu});
  // Isotropic stiffness in Voigt form with engineering shears (e.g. Zienkiewicz & Taylor).
  Mat6 expected = Mat6::Zero();
  const double c = E / ((1 + nu) * (1 - 2 * nu));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) expected(i, j) = c * (i == j ? 1 - nu : nu);
    expected(i + 3, i + 3) = E / (2 * (1 + nu));
  }
  std::mt19937_64 rng(2);
  const Mat6 tangent = algorithmic_tangent(model, State{}, test::random_symmetric(rng, 1e-4));
  CHECK((tangent - expected).norm() <= 1e-6 * expected.norm());
}
