// The numerical-stability stress test, short version: 1e5 random increments per model and integrator.
#include <catch2/catch.hpp>

#include "constitutive/stress_test.h"

using namespace soilsph;

TEST_CASE("stress test: 1e5 random increments per model and integrator keep every state admissible",
          "[stress-test]") {
  StressTestOptions options;
  options.increments = 100000;
  options.seed = 20261124;
  for (const auto& [name, label, material] : stress_test_materials()) {
    for (Integrator scheme : kIntegrators) {
      const StressTestResult r = run_stress_test(material, scheme, options);
      INFO(name << ", " << integrator_name(scheme) << ": " << r.plastic << " plastic, " << r.extension
                << " extension, " << r.unloading << " unloading, " << r.at_apex << " at apex, "
                << r.near_zero_pressure << " near p'=0, " << r.near_critical_state << " near CSL, max f "
                << r.max_yield << ", " << r.seconds << " s; " << r.first_problem);
      CHECK(r.increments == options.increments);
      CHECK(r.failures == 0);
      CHECK(r.violations == 0);
      CHECK(r.plastic > options.increments / 10);  // the walk does exercise plasticity
      if (std::holds_alternative<DruckerPrager>(material)) CHECK(r.at_apex > 10);
      if (label == "mc") CHECK(r.at_apex > 10);  // the Mohr-Coulomb apex, without a cut-off
      if (std::holds_alternative<ModifiedCamClay>(material)) {
        CHECK(r.near_zero_pressure > 100);
        CHECK(r.near_critical_state > 100);
      }
    }
  }
}
