// `soilsph calibrate FILE.toml [--out DIR]`: fits a material's parameters to measured curves
// (verification/calibration/calibration_file.h) and writes the answer into DIR: fit.json, the
// calibrated material.toml, curves-NAME.csv per experiment, history.csv, and the figures
// (scripts/plot_calibration.py).
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"
#include "soilsph/version.h"
#include "verification/calibration/calibrate.h"
#include "verification/calibration/fit_output.h"

namespace soilsph::cli {

namespace {
struct CalibrateOptions {
  std::string file;
  std::string out = "results/calibration";
  std::string python = "/usr/bin/python3";  // Debian's, with matplotlib (README)
  bool plots = true;
};

/// Single-quotes `s` for the shell.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void run(const CalibrateOptions& o) {
  using namespace calibration;
  const CalibrationFile file = read_calibration_file(o.file);
  const Calibration result = calibrate(file);
  const std::vector<std::string> provenance = {std::string("soilsph ") + kVersion,
                                               "command: " + invocation()};
  write_calibration(o.out, file, result, provenance);
  std::cout << calibration_summary(file, result)
            << "calibrated material: " << (std::filesystem::path(o.out) / "material.toml").string()
            << std::endl;
  if (!o.plots) return;
  if (!std::filesystem::exists(o.python)) {
    std::cerr << "note: " << o.python << " not found: no figures (scripts/plot_calibration.py draws them)\n";
    return;
  }
  const std::string command = quoted(o.python) + " " +
                              quoted((data_dir() / "scripts" / "plot_calibration.py").string()) + " " + quoted(o.out);
  if (std::system(command.c_str()) != 0) throw std::runtime_error("plotting failed: " + command);
}
}  // namespace

void add_calibrate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "calibrate",
      "Fit a material's parameters to measured curves; write the calibrated material and fit.json");
  auto o = std::make_shared<CalibrateOptions>();
  cmd->add_option("FILE", o->file,
                  "calibration file: material, [fit] parameters with bounds, [[experiment]] programme, data, "
                  "against, match (docs/reference/calibration.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", o->out,
                  "output folder (fit.json, material.toml, curves-*.csv, history.csv, figures)")
      ->capture_default_str();
  cmd->add_flag("!--no-plots", o->plots, "Skip the PNG figures");
  cmd->add_option("--python", o->python, "Python with matplotlib for the figures")->capture_default_str();
  cmd->callback([o] { run(*o); });
}

}  // namespace soilsph::cli
