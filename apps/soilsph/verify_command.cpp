// `soilsph verify [--out DIR]`: runs every verification case (verification/cases/*.toml), compares each
// integrator with the CVODE reference and the closed forms, and writes DIR/report.md, the CSVs and the
// plots (scripts/plot_verification.py). Exits non-zero if any run is outside its tolerance.
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"
#include "soilsph/version.h"
#include "verification/report/report_writer.h"

namespace soilsph::cli {

namespace {
struct VerifyOptions {
  std::string out = "results/verification";
  std::string cases;  ///< empty: the shipped cases (data_dir()/verification/cases)
  std::string python = "/usr/bin/python3";  // Debian's, with matplotlib (scripts/setup.sh)
  bool plots = true;
};

void run(const VerifyOptions& o) {
  using namespace verification;
  const std::vector<VerificationCase> cases =
      read_cases(o.cases.empty() ? (data_dir() / "verification" / "cases").string() : o.cases);
  std::vector<CaseResult> results;
  std::size_t failed = 0;
  for (const VerificationCase& c : cases) {
    results.push_back(run_case(c));
    for (const IntegratorRun& run : results.back().runs) {
      failed += run.passed ? 0 : 1;
      std::cout << (run.passed ? "  pass  " : "  FAIL  ") << c.name << " [" << run.integrator << "]"
                << (run.failure.empty() ? "" : ": " + run.failure) << '\n';
    }
  }
  const std::vector<std::string> provenance = {std::string("soilsph ") + kVersion, "command: " + invocation()};
  write_report(o.out, results, provenance);
  std::cout << "report: " << (std::filesystem::path(o.out) / "report.md").string() << '\n';
  if (o.plots) {
    const std::string command = shell_quoted(o.python) + " " +
                                shell_quoted((data_dir() / "scripts" / "plot_verification.py").string()) + " " +
                                shell_quoted(o.out);
    if (std::system(command.c_str()) != 0) throw std::runtime_error("plotting failed: " + command);
  }
  if (failed > 0)
    throw std::runtime_error("verification failed: " + std::to_string(failed) + " run(s) outside tolerance");
}
}  // namespace

void add_verify_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "verify",
      "Run every verification case against the CVODE reference and the closed forms; write a report");
  auto o = std::make_shared<VerifyOptions>();
  cmd->add_option("--out", o->out, "Output folder (report.md, csv/, plots/, cases.json)")
      ->capture_default_str();
  cmd->add_option("--cases", o->cases,
                  "A case file or a folder of *.toml case files (default: the shipped cases, soilsph examples "
                  "lists them)")
      ->check(CLI::ExistingPath);
  cmd->add_flag("!--no-plots", o->plots, "Skip the PNG plots");
  cmd->add_option("--python", o->python, "Python with matplotlib for the plots")->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace soilsph::cli
