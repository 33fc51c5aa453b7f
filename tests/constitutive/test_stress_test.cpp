// The numerical-stability stress test, short version: 1e5 random increments per model and integrator.
#include <catch2/catch.hpp>

#include <algorithm>

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

TEST_CASE("stress test: dust increments it found keep p' >= 0 and p_c bounded with every MCC integrator",
          "[stress-test]") {
  // The first problems of `soilsph stress-test --increments 1000000 --seed 20261124` once free-surface
  // ("dust") states were added: extension from the cap's tip of a 0.26 Pa surface (pressure-dependent
  // K) and shear from a 11 Pa surface (constant E), each with its spin. `substep` returned
  // p' = −1.7e5 Pa with p_c = 1.2e20 Pa and p' = −1.4e6 Pa with p_c = 3.9e19 Pa: its drift correction
  // judged f relative to the runaway p_c. On the surface 0 ≤ p ≤ p_c, and one increment of stress
  // scale S cannot build a surface of 1e19 Pa: p ≥ −1e-8 S, p_c ≤ 10 max(p_c,n, S).
  struct Case {
    const char* label;
    double stress[9], pc, strain[9], spin[9];
  };
  const Case cases[] = {
      {"mcc",
       {-0.27836163837083677, 0.01075802868074361, -0.0044998647887303737, 0.010758028680743608,
        -0.24750414531586862, 0.0031393849922976328, -0.0044998647887303745, 0.0031393849922976324,
        -0.24318767118031473},
       0.25934042219736075,
       {0.00046652986653855459, -6.4037113691295145e-05, 2.6785446955396619e-05, -6.4037113691295145e-05,
        0.00028285078333398922, -1.8687181653089224e-05, 2.6785446955396619e-05, -1.8687181653089224e-05,
        0.00025715699780384939},
       {0, -0.00030566875700470685, -0.00016930445936696071, 0.00030566875700470685, 0, 0.00015916212358667368,
        0.00016930445936696071, -0.00015916212358667368, 0}},
      {"mcc-constant-E",
       {-5.6876665353335962, 0.26236062888175771, -4.33554130895154, 0.26236062888175765, -5.3132400641719864,
        -0.24308950839685808, -4.33554130895154, -0.24308950839685808, -7.5064095324854057},
       11.076697561407407,
       {-2.1063763570953433e-05, -2.7708222665241256e-05, 0.00045789370852370825, -2.7708222665241256e-05,
        -6.0606852257802364e-05, 2.5675055958950504e-05, 0.00045789370852370825, 2.5675055958950504e-05,
        0.00017102443769735783},
       {0, -0.00015831873923340947, -0.00057245182954311451, 0.00015831873923340947, 0, 0.00047528609736550791,
        0.00057245182954311451, -0.00047528609736550791, 0}}};
  const auto materials = stress_test_materials();
  for (const Case& c : cases) {
    const auto it = std::find_if(materials.begin(), materials.end(), [&](const auto& m) { return m.label == c.label; });
    REQUIRE(it != materials.end());
    const auto& base = std::get<ModifiedCamClay>(it->material);
    State start;
    Mat3 d_eps, d_spin;
    for (int i = 0; i < 9; ++i)
      start.stress(i / 3, i % 3) = c.stress[i], d_eps(i / 3, i % 3) = c.strain[i], d_spin(i / 3, i % 3) = c.spin[i];
    start.pc = c.pc;
    const double scale = increment_scale(base, start, d_eps);
    for (Integrator scheme : kIntegrators) {
      auto params = base.params();
      params.integrator = scheme;
      const State next = ModifiedCamClay(params).update(start, d_eps, d_spin);
      INFO(c.label << ", " << integrator_name(scheme) << ": p' = " << mean_pressure(next.stress) << " Pa, p_c = "
                   << next.pc << " Pa, scale " << scale << " Pa");
      CHECK(mean_pressure(next.stress) >= -1e-8 * scale);
      CHECK(next.pc <= 10.0 * std::max(start.pc, scale));
    }
  }
}

TEST_CASE("stress test: the error-controlled MCC implicit keeps every state admissible", "[stress-test]") {
  // Its accepted doublings are extrapolated off the surface and put back by the drift correction
  // (implicit_cam_clay.cpp): the same walk as above with `implicit_tolerance`, loose (most
  // sub-increments doubled once and extrapolated) and tight (many per increment), both elasticities.
  StressTestOptions options;
  options.increments = 200000;
  options.seed = 20261204;
  for (const char* label : {"mcc", "mcc-constant-E"}) {
    const auto materials = stress_test_materials();
    const auto it =
        std::find_if(materials.begin(), materials.end(), [&](const auto& m) { return m.label == label; });
    REQUIRE(it != materials.end());
    for (double tolerance : {1e-2, 1e-5}) {
      auto params = std::get<ModifiedCamClay>(it->material).params();
      params.implicit_tolerance = tolerance;
      const StressTestResult r = run_stress_test(ModifiedCamClay(params), Integrator::Implicit, options);
      INFO(label << ", implicit_tolerance " << tolerance << ": " << r.plastic << " plastic, max f "
                 << r.max_yield << ", " << r.seconds << " s; " << r.first_problem);
      CHECK(r.increments == options.increments);
      CHECK(r.failures == 0);
      CHECK(r.violations == 0);
      CHECK(r.plastic > options.increments / 2);
      CHECK(r.near_zero_pressure > 10);
    }
  }
}
