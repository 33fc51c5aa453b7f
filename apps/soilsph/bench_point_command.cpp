// `soilsph bench point [--out DIR]`: the work–precision benchmark of the stress integrators
// (error against CVODE versus CPU time per path), written as CSV; plot with
// scripts/plot_work_precision.py.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/soilsph/commands.h"
#include "verification/work_precision.h"

namespace soilsph::cli {

namespace {
Material table1_material(const std::string& dir, const std::string& name) {
  return load_material(dir + "/data/materials/" + name + ".toml");
}
}  // namespace

void add_bench_command(CLI::App& app) {
  auto* bench = app.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  auto* point = bench->add_subcommand(
      "point",
      "Work-precision of explicit, substep and implicit against CVODE on triaxial and oedometer paths");
  struct Options {
    std::string out = "results/bench-point";
    std::string data = ".";
    std::vector<int> increments;
    double min_seconds = 0.02;
  };
  auto o = std::make_shared<Options>();
  point->add_option("--out", o->out, "output directory (work_precision.csv)")->capture_default_str();
  point->add_option("--root", o->data, "project root holding data/materials/")->capture_default_str();
  point->add_option("--increments", o->increments, "increment counts (default 1,2,5,...,10000)")
      ->delimiter(',');
  point->add_option("--min-seconds", o->min_seconds, "CPU time to spend per measurement (median of repeats)")
      ->capture_default_str();
  point->callback([o] {
    using namespace verification;
    WorkPrecisionOptions options;
    if (!o->increments.empty()) options.increments = o->increments;
    options.min_seconds = o->min_seconds;
    std::filesystem::create_directories(o->out);
    std::vector<WorkPrecisionRow> rows;
    for (const char* name : {"mcc-table1", "dp-table1"}) {
      const Material material = table1_material(o->data, name);
      for (LoadPath path : {LoadPath::TriaxialDrained, LoadPath::TriaxialUndrained, LoadPath::Oedometer}) {
        PointTest test;  // p_initial 100 kPa, OCR 1, to eps_a = 0.1
        test.path = path;
        const auto part = work_precision(name, material, test, options, [](const WorkPrecisionRow& r) {
          std::printf("%-11s %-19s %-15s %6d  err_q %.3e  err_p %.3e  %.3e s\n", r.material.c_str(),
                      r.path.c_str(), r.integrator.c_str(), r.increments, r.error_q, r.error_p,
                      r.cpu_seconds);
          std::fflush(stdout);
        });
        rows.insert(rows.end(), part.begin(), part.end());
      }
    }
    std::ofstream csv(o->out + "/work_precision.csv");
    write_work_precision_csv(csv, rows);
    std::printf("wrote %s/work_precision.csv\n", o->out.c_str());
  });
  add_bench_collapse_command(*bench);
}

}  // namespace soilsph::cli
