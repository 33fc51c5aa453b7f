// The reported 95 % intervals contain the true parameters about 95 % of the time: Modified Cam-Clay
// data with Gaussian noise (1 % of each column's range) from many seeds, each fitted on its own.
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

#include "tests/calibration/calibration_fixtures.h"
#include "verification/calibration/calibrate.h"

using namespace soilsph::calibration;
using namespace soilsph::calibration::testing;

namespace {

struct Coverage {
  int covered = 0;
  int intervals = 0;
};

Coverage coverage(unsigned first_seed, unsigned seeds) {
  const std::string common =
      "model = \"modified-cam-clay\"\ndensity = 1800\npoisson_ratio = 0.25\n"
      "initial_void_ratio = 1.0\nelasticity = \"pressure-dependent\"\nintegrator = \"implicit\"\n";
  const std::vector<std::pair<std::string, double>> truth = {
      {"compression_index", 0.2}, {"swelling_index", 0.04}, {"friction_angle", 28.0}};
  const std::string true_material =
      common + "compression_index = 0.2\nswelling_index = 0.04\nfriction_angle = 28\n";
  const std::string start =
      common + "compression_index = 0.22\nswelling_index = 0.036\nfriction_angle = 30\n";
  const std::string fit =
      "parameters = { compression_index = [0.05, 0.5], swelling_index = [0.005, 0.045], friction_angle = "
      "[15, 45] }\n";
  const std::vector<SyntheticTest> tests = cam_clay_tests(40);
  Coverage c;
  for (unsigned seed = first_seed; seed < first_seed + seeds; ++seed) {
    const TempDir dir;
    std::vector<std::string> csvs;
    for (std::size_t k = 0; k < tests.size(); ++k)
      csvs.push_back(
          measured_csv(dir, true_material, tests[k], 2, 0.01, 1000 * seed + static_cast<unsigned>(k)));
    const Calibration result =
        calibrate(read_calibration_file(calibration_file(dir, start, fit, tests, csvs)));
    for (std::size_t k = 0; k < truth.size(); ++k) {
      const ParameterEstimate& e = result.statistics.parameters[k];
      c.covered += e.lower_95 <= truth[k].second && truth[k].second <= e.upper_95 ? 1 : 0;
      ++c.intervals;
    }
  }
  return c;
}

}  // namespace

TEST_CASE("95 % intervals cover the true values: 20 seeds of noisy Cam-Clay data", "[calibration]") {
  // 60 intervals at a true coverage of 0.95: 57 expected, and 50 or fewer has a binomial
  // probability of about 0.1 %; intervals half as wide as they should be (coverage ~0.68) give ~41.
  const Coverage c = coverage(1, 20);
  INFO(c.covered << " of " << c.intervals << " intervals contain the truth");
  CHECK(c.covered >= 51);
}

TEST_CASE("Coverage study: 250 seeds of noisy Cam-Clay data", "[long]") {
  const Coverage c = coverage(1001, 250);
  const double fraction = static_cast<double>(c.covered) / c.intervals;
  std::cout << "calibration coverage study: " << c.covered << " of " << c.intervals
            << " 95 % intervals contain the truth (" << 100.0 * fraction << " %)\n";
  // 750 intervals: a binomial standard deviation of 0.8 %; the linearised intervals are allowed
  // to be a little optimistic or pessimistic, not more.
  CHECK(fraction > 0.92);
  CHECK(fraction < 0.98);
}
