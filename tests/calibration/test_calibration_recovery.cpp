// A calibration gives back the parameters that made its data: synthetic readings from the point
// driver with known parameters, a start 30 % off, and the fit recovering the truth to 1e-6.
#include <catch2/catch.hpp>
#include <cmath>

#include "tests/calibration/calibration_fixtures.h"
#include "verification/calibration/calibrate.h"

using namespace soilsph::calibration;
using namespace soilsph::calibration::testing;

namespace {

/// The fit from `start_material` against data made with `true_material`; REQUIREs each
/// `expected` key's fitted value within `tolerance` (relative) of its true value.
void check_recovery(const std::string& true_material, const std::string& start_material,
                    const std::string& fit, const std::vector<SyntheticTest>& tests,
                    const std::vector<std::pair<std::string, double>>& expected, double tolerance) {
  const TempDir dir;
  std::vector<std::string> csvs;
  for (const SyntheticTest& test : tests) csvs.push_back(measured_csv(dir, true_material, test, 3));
  const CalibrationFile file = read_calibration_file(calibration_file(dir, start_material, fit, tests, csvs));
  const Calibration result = calibrate(file);
  INFO(result.starts[result.best].fit.stop);
  REQUIRE(result.statistics.parameters.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const ParameterEstimate& e = result.statistics.parameters[k];
    INFO(e.key << " = " << e.value << ", true " << expected[k].second << ", start " << e.start);
    CHECK(e.key == expected[k].first);
    CHECK(std::abs(e.start / expected[k].second - 1.0) > 0.29);  // the start is 30 % off
    CHECK(std::abs(e.value / expected[k].second - 1.0) < tolerance);
  }
  CHECK(result.statistics.cost < 1e-12);
}

const std::string kCamClay =
    "model = \"modified-cam-clay\"\ndensity = 1800\npoisson_ratio = 0.25\ninitial_void_ratio = 1.0\n"
    "elasticity = \"pressure-dependent\"\nintegrator = \"implicit\"\n";

}  // namespace

TEST_CASE(
    "Modified Cam-Clay: lambda, kappa and M recovered from CU tests at OCR 1, 2, 4 and an isotropic test",
    "[calibration]") {
  // M = 6 sin φ / (3 − sin φ) (eq 26): φ is the key that sets it.
  const std::string truth =
      kCamClay + "compression_index = 0.2\nswelling_index = 0.04\nfriction_angle = 28\n";
  const std::string start =
      kCamClay + "compression_index = 0.26\nswelling_index = 0.028\nfriction_angle = 36.4\n";
  const std::string fit =
      "parameters = { compression_index = [0.05, 0.5], swelling_index = [0.005, 0.045], friction_angle = "
      "[15, 45] }\n";
  check_recovery(truth, start, fit, cam_clay_tests(60),
                 {{"compression_index", 0.2}, {"swelling_index", 0.04}, {"friction_angle", 28.0}}, 1e-6);
}

TEST_CASE("Modified Cam-Clay: the dogleg trust region recovers them too", "[calibration]") {
  const std::string truth =
      kCamClay + "compression_index = 0.2\nswelling_index = 0.04\nfriction_angle = 28\n";
  const std::string start =
      kCamClay + "compression_index = 0.14\nswelling_index = 0.052\nfriction_angle = 19.6\n";
  const std::string fit =
      "method = \"dogleg\"\nparameters = { compression_index = [0.05, 0.5], swelling_index = "
      "[0.005, 0.06], friction_angle = [15, 45] }\n";
  check_recovery(truth, start, fit, cam_clay_tests(60),
                 {{"compression_index", 0.2}, {"swelling_index", 0.04}, {"friction_angle", 28.0}}, 1e-6);
}

TEST_CASE("Drucker-Prager and Mohr-Coulomb: phi, c, psi and E recovered from drained tests",
          "[calibration]") {
  for (const std::string model : {"drucker-prager", "mohr-coulomb"}) {
    DYNAMIC_SECTION(model) {
      const std::string common =
          "model = \"" + model + "\"\ndensity = 1900\npoisson_ratio = 0.3\nintegrator = \"implicit\"\n";
      const std::string truth =
          common + "friction_angle = 32\ncohesion = 10000\ndilatancy_angle = 8\nyoung_modulus = 20e6\n";
      const std::string start =
          common + "friction_angle = 22.4\ncohesion = 13000\ndilatancy_angle = 5.6\nyoung_modulus = 26e6\n";
      const std::string fit =
          "parameters = { friction_angle = [10, 45], cohesion = [1000, 50000], dilatancy_angle = "
          "[0, 20], young_modulus = [1e6, 1e8] }\n";
      check_recovery(
          truth, start, fit, drained_tests(50),
          {{"friction_angle", 32.0}, {"cohesion", 1e4}, {"dilatancy_angle", 8.0}, {"young_modulus", 20e6}},
          1e-6);
    }
  }
}

TEST_CASE("Several starts: each fitted, the lowest misfit kept, all recorded", "[calibration]") {
  const TempDir dir;
  const std::string truth =
      kCamClay + "compression_index = 0.2\nswelling_index = 0.04\nfriction_angle = 28\n";
  const std::string start =
      kCamClay + "compression_index = 0.26\nswelling_index = 0.028\nfriction_angle = 36.4\n";
  const std::string fit =
      "starts = 3\nseed = 7\nparameters = { compression_index = [0.05, 0.5], swelling_index = "
      "[0.005, 0.045], friction_angle = [15, 45] }\n";
  const std::vector<SyntheticTest> tests = cam_clay_tests(40);
  std::vector<std::string> csvs;
  for (const SyntheticTest& test : tests) csvs.push_back(measured_csv(dir, truth, test, 2));
  const Calibration result = calibrate(read_calibration_file(calibration_file(dir, start, fit, tests, csvs)));
  REQUIRE(result.starts.size() == 3);
  CHECK(result.starts[0].start == std::vector<double>{0.26, 0.028, 36.4});
  // Random starts lie in the middle 80 % of the bounds in ln x: 15 · 3^0.1 to 15 · 3^0.9 degrees.
  for (std::size_t s = 1; s < 3; ++s) {
    CHECK(result.starts[s].start != result.starts[0].start);
    CHECK(result.starts[s].start[2] > 15.0 * std::pow(3.0, 0.1));
    CHECK(result.starts[s].start[2] < 15.0 * std::pow(3.0, 0.9));
  }
  for (const StartRun& run : result.starts)
    CHECK(result.starts[result.best].fit.residuals.squaredNorm() <= run.fit.residuals.squaredNorm());
  CHECK(std::abs(result.values[0] / 0.2 - 1.0) < 1e-6);
  CHECK(std::abs(result.values[2] / 28.0 - 1.0) < 1e-6);
}

TEST_CASE(
    "A UMAT's props: libsoilsph_umat's Drucker-Prager fitted by props(N) to the built-in model's curves",
    "[calibration][umat]") {
  // PROPS = E, nu, phi, c, psi (docs/reference/umat-library.md); the data come from the built-in
  // model with the same values, so the fit must find them in the UMAT's props.
  const std::string truth =
      "model = \"drucker-prager\"\ndensity = 1900\npoisson_ratio = 0.3\nintegrator = \"implicit\"\n"
      "friction_angle = 32\ncohesion = 10000\ndilatancy_angle = 8\nyoung_modulus = 20e6\n";
  const std::string start = "model = \"umat\"\nlibrary = \"" + std::string(SOILSPH_UMAT_LIBRARY) +
                            "\"\nname = \"drucker-prager:implicit\"\nprops = [26e6, 0.3, 22.4, 13000, 5.6]\n"
                            "state_variables = 4\ndensity = 1900\nthread_safe = true\n";
  const std::string fit =
      "parameters = { \"props(1)\" = [1e6, 1e8], \"props(3)\" = [10, 45], \"props(4)\" = [1000, 50000], "
      "\"props(5)\" = [0, 20] }\n";
  check_recovery(truth, start, fit, drained_tests(50),
                 {{"props(1)", 20e6}, {"props(3)", 32.0}, {"props(4)", 1e4}, {"props(5)", 8.0}}, 1e-6);
}

TEST_CASE("A UMAT not declared thread-safe is called one call at a time", "[calibration][umat]") {
  // ONE-AT-A-TIME returns a NaN stress when another call is in progress, as a UMAT whose SAVE
  // variables two threads share would go wrong: with thread_safe left false, the Jacobian's columns
  // must not run in parallel, and the fit recovers E and nu of Hooke's law.
  const std::string truth =
      "model = \"linear-elastic\"\ndensity = 1900\nyoung_modulus = 20e6\npoisson_ratio = 0.3\n";
  const std::string start =
      "model = \"umat\"\nlibrary = \"" + std::string(SOILSPH_UMAT_MISBEHAVING_C) +
      "\"\nsymbol = \"umat_elastic_c\"\nname = \"ONE-AT-A-TIME\"\nprops = [26e6, 0.21]\n"
      "density = 1900\n";
  const std::string fit = "parameters = { \"props(1)\" = [1e6, 1e8], \"props(2)\" = [0.05, 0.45] }\n";
  check_recovery(truth, start, fit, drained_tests(20), {{"props(1)", 20e6}, {"props(2)", 0.3}}, 1e-6);
}
