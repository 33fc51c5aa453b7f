// `soilsph stress-test [--increments N] [--seed S] [--model M ...] [--integrator I ...]`: the long
// numerical-stability stress test.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/range_validator.h"
#include "constitutive/stress_test.h"

namespace soilsph::cli {

void add_stress_test_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "stress-test",
      "Random strain walks through every model with every integrator, checking each increment");
  auto options = std::make_shared<StressTestOptions>();
  options->increments = 10'000'000;
  cmd->add_option("--increments", options->increments, "increments per model and integrator")
      ->capture_default_str()
      ->transform(whole_number_in(1, 1'000'000'000'000));  // about 1 µs each: beyond it a run takes weeks
  cmd->add_option("--seed", options->seed, "random seed (the walk is reproducible)")->capture_default_str();
  cmd->add_option("--max-increment", options->max_increment, "largest strain-increment norm")
      ->capture_default_str()
      ->check(in_range(Range::closed(1e-6, 1.0)));
  // Filters, so that one slow pair (Mohr–Coulomb substep: ~140 µs per increment) can run long alone.
  auto models = std::make_shared<std::vector<std::string>>();
  auto schemes = std::make_shared<std::vector<std::string>>();
  std::vector<std::string> model_names;
  for (const auto& m : stress_test_materials())
    if (std::find(model_names.begin(), model_names.end(), model_name(m.material)) == model_names.end())
      model_names.emplace_back(model_name(m.material));
  cmd->add_option("--model", *models, "only these models (repeatable; default all)")
      ->check(CLI::IsMember(model_names));
  cmd->add_option("--integrator", *schemes, "only these integrators (repeatable; default all)")
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(kIntegratorNames), std::end(kIntegratorNames))));
  const auto chosen = [](const std::vector<std::string>& wanted, std::string_view name) {
    return wanted.empty() || std::find(wanted.begin(), wanted.end(), name) != wanted.end();
  };
  cmd->callback([options, models, schemes, chosen] {
    std::printf(
        "# stress test: %ld increments per model x integrator, seed %llu, |d_eps| log-uniform in [1e-6, "
        "%g]\n",
        options->increments, static_cast<unsigned long long>(options->seed), options->max_increment);
    std::printf(
        "# checks: finite state, normalized f <= %g, Δλ >= 0; MCC p' >= -%g S and p_c > 0, S = the "
        "increment's stress scale (p' compression-positive; MCC f relative to max(M p_c, S)^2)\n",
        options->yield_tolerance, options->yield_tolerance);
    std::printf("%-50s %-9s %10s %10s %9s %9s %9s %9s %8s %10s %11s %9s\n", "material", "scheme", "plastic",
                "extension", "unloading", "apex", "p'<.01pc", "near-CSL", "failures", "violations", "max f",
                "seconds");
    long problems = 0;
    for (const auto& [name, label, material] : stress_test_materials()) {
      if (!chosen(*models, model_name(material))) continue;
      for (Integrator scheme : kIntegrators) {
        if (!chosen(*schemes, integrator_name(scheme))) continue;
        const StressTestResult r = run_stress_test(material, scheme, *options);
        std::printf("%-50s %-9s %10ld %10ld %9ld %9ld %9ld %9ld %8ld %10ld %11.3g %9.1f\n", name.c_str(),
                    std::string(integrator_name(scheme)).c_str(), r.plastic, r.extension, r.unloading,
                    r.at_apex, r.near_zero_pressure, r.near_critical_state, r.failures, r.violations,
                    r.max_yield, r.seconds);
        if (!r.first_problem.empty()) {
          std::printf("#   first problem: %s\n", r.first_problem.c_str());
          // What reproduces it: the state before the increment and the increment (row-major 3x3, Pa
          // tension-positive; strain and spin).
          auto print = [](const char* label, const Mat3& m) {
            std::printf("#     %s", label);
            for (int i = 0; i < 9; ++i) std::printf(" %.17g", m(i / 3, i % 3));
            std::printf("\n");
          };
          print("stress", r.problem_start.stress);
          std::printf("#     p_c %.17g\n", r.problem_start.pc);
          print("strain increment", r.problem_strain);
          print("spin increment", r.problem_spin);
        }
        std::fflush(stdout);
        problems += r.failures + r.violations;
      }
    }
    std::printf("%s: %ld problems\n", problems == 0 ? "PASSED" : "FAILED", problems);
    if (problems != 0) throw std::runtime_error("stress test: " + std::to_string(problems) + " problems");
  });
}

}  // namespace soilsph::cli
