// `soilsph stress-test [--increments N] [--seed S] [--model M ...] [--integrator I ...]
// [--material FILE [--statev-range K:LO:HI ...] [--tangent-every N] [--tangent-tolerance T]]`: the long
// numerical-stability stress test, of the built-in models or of the material of a file (a UMAT
// plug-in runs its own update).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/range_validator.h"
#include "constitutive/stress_test.h"

namespace soilsph::cli {

namespace {

/// "K:LO:HI" of --statev-range; LO or HI may be "inf" or "-inf".
StateVariableRange parse_state_range(const std::string& text) {
  std::istringstream in(text);
  StateVariableRange r;
  char colon1 = 0;
  std::string lo, hi;
  if (!(in >> r.index >> colon1) || colon1 != ':' || !std::getline(in, lo, ':') || !std::getline(in, hi) ||
      r.index < 1)
    throw CLI::ValidationError("--statev-range", text + " is not K:LO:HI (K from 1, e.g. 1:0:inf)");
  try {
    r.lo = std::stod(lo), r.hi = std::stod(hi);
  } catch (const std::exception&) {
    throw CLI::ValidationError("--statev-range", text + ": LO and HI must be numbers (or inf, -inf)");
  }
  if (!(r.lo <= r.hi)) throw CLI::ValidationError("--statev-range", text + ": LO must not exceed HI");
  return r;
}

void print_problem(const StressTestResult& r) {
  if (r.first_problem.empty()) return;
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

/// A UMAT plug-in's walk: one row, and the tangent comparison below it.
long run_umat(const std::string& file, const UmatModel& umat, const StressTestOptions& options) {
  std::printf(
      "# UMAT %s (%s): checks: finite STRESS and STATEV, STATEV in the --statev-range ranges, DDSDDE "
      "against central differences every %ld increments (relative Frobenius difference <= %g)\n",
      file.c_str(), umat.params().library.c_str(), options.tangent_every, options.tangent_tolerance);
  std::printf("%-50s %10s %10s %8s %10s %13s %11s %9s\n", "material", "increments", "extension", "failures",
              "violations", "tangent-check", "worst-error", "seconds");
  const StressTestResult r = run_umat_stress_test(umat, options);
  std::printf("%-50s %10ld %10ld %8ld %10ld %13ld %11.3g %9.1f\n", file.c_str(), r.increments, r.extension,
              r.failures, r.violations, r.tangent_checks, r.worst_tangent_error, r.seconds);
  print_problem(r);
  return r.failures + r.violations;
}

}  // namespace

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
  auto material_file = std::make_shared<std::string>();
  auto ranges = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--material", *material_file,
                  "walk the material of this file instead of the built-in list (a umat material: its own "
                  "update, checked for finite results, --statev-range and its DDSDDE)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--statev-range", *ranges,
                  "K:LO:HI: a umat material's STATEV(K) must stay in [LO, HI] after every increment "
                  "(repeatable; inf allowed)");
  cmd->add_option("--tangent-every", options->tangent_every,
                  "a umat material: compare DDSDDE with central differences every N increments (0: never)")
      ->capture_default_str()
      ->transform(whole_number_in(0, 1'000'000'000));
  cmd->add_option("--tangent-tolerance", options->tangent_tolerance,
                  "a umat material: accepted relative difference of DDSDDE and central differences")
      ->capture_default_str()
      ->check(in_range(Range::closed(1e-12, 1.0)));
  const auto chosen = [](const std::vector<std::string>& wanted, std::string_view name) {
    return wanted.empty() || std::find(wanted.begin(), wanted.end(), name) != wanted.end();
  };
  cmd->callback([options, models, schemes, chosen, material_file, ranges] {
    for (const std::string& text : *ranges) options->state_ranges.push_back(parse_state_range(text));
    std::vector<StressTestMaterial> materials = stress_test_materials();
    if (!material_file->empty()) {
      const Material material = load_material(*material_file);
      if (const auto* umat = std::get_if<UmatModel>(&material)) {
        std::printf("# stress test: %ld increments, seed %llu, |d_eps| log-uniform in [1e-6, %g]\n",
                    options->increments, static_cast<unsigned long long>(options->seed),
                    options->max_increment);
        const long problems = run_umat(*material_file, *umat, *options);
        std::printf("%s: %ld problems\n", problems == 0 ? "PASSED" : "FAILED", problems);
        if (problems != 0) throw std::runtime_error("stress test: " + std::to_string(problems) + " problems");
        return;
      }
      if (!ranges->empty()) throw CLI::ValidationError("--statev-range", "applies to a umat material only");
      materials = {{*material_file, "file", material}};
    }
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
    for (const auto& [name, label, material] : materials) {
      if (!chosen(*models, model_name(material))) continue;
      for (Integrator scheme : kIntegrators) {
        if (!chosen(*schemes, integrator_name(scheme))) continue;
        const StressTestResult r = run_stress_test(material, scheme, *options);
        std::printf("%-50s %-9s %10ld %10ld %9ld %9ld %9ld %9ld %8ld %10ld %11.3g %9.1f\n", name.c_str(),
                    std::string(integrator_name(scheme)).c_str(), r.plastic, r.extension, r.unloading,
                    r.at_apex, r.near_zero_pressure, r.near_critical_state, r.failures, r.violations,
                    r.max_yield, r.seconds);
        print_problem(r);
        std::fflush(stdout);
        problems += r.failures + r.violations;
      }
    }
    std::printf("%s: %ld problems\n", problems == 0 ? "PASSED" : "FAILED", problems);
    if (problems != 0) throw std::runtime_error("stress test: " + std::to_string(problems) + " problems");
  });
}

}  // namespace soilsph::cli
