// `soilsph bench point [--out DIR]`: the work–precision benchmark of the stress integrators
// (error against CVODE versus CPU time per path), written as CSV; plot with
// scripts/plot_work_precision.py.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"
#include "verification/work_precision.h"

namespace soilsph::cli {

namespace {
Material table1_material(const std::string& dir, const std::string& name) {
  return load_material(dir + "/data/materials/" + name + ".toml");
}
}  // namespace

void add_bench_command(CLI::App& app) {
  auto* bench = app.add_subcommand(
      "bench", "Benchmarks: point (the stress integrators' error against cost), collapse (SPH speed), scaling (SPH "
      "cost against the particle count)");
  bench->require_subcommand(1);
  auto* point = bench->add_subcommand(
      "point",
      "Work-precision of explicit, substep and implicit against CVODE on triaxial and oedometer paths");
  struct Options {
    std::string out = "results/bench-point";
    std::string data;  ///< empty: the shipped data (data_dir())
    std::vector<int> increments;
    double min_seconds = 0.02;
    std::string only;
    std::string material;  ///< a material file run instead of the built-in cases
    std::vector<double> path_tolerances = {1e-3, 1e-4, 1e-5};
    std::vector<double> substep_tolerances = verification::WorkPrecisionOptions{}.substep_tolerances;
    std::vector<double> implicit_tolerances = verification::WorkPrecisionOptions{}.implicit_tolerances;
  };
  auto o = std::make_shared<Options>();
  point->add_option("--out", o->out, "output directory (work_precision.csv)")->capture_default_str();
  point->add_option("--root", o->data, "folder holding data/materials/ (default: the shipped data)");
  point->add_option("--increments", o->increments, "increment counts (default 1,2,5,...,10000)")
      ->delimiter(',');
  point->add_option("--min-seconds", o->min_seconds, "CPU time to spend per measurement (median of repeats)")
      ->capture_default_str();
  point->add_option("--path-tolerances", o->path_tolerances,
                    "driver sub-step tolerances run on the triaxial paths of the K = (1+e0)p/kappa cases "
                    "(labelled +path(TOL); the Table 1 cases run without)")
      ->delimiter(',')
      ->capture_default_str();
  point->add_option("--substep-tolerances", o->substep_tolerances, "substep_tolerance values, one row each")
      ->delimiter(',')
      ->capture_default_str();
  point->add_option("--implicit-tolerances", o->implicit_tolerances,
                    "MCC implicit_tolerance values, one row each besides plain implicit")
      ->delimiter(',')
      ->capture_default_str();
  point->add_option("--case", o->only,
                    "run one case: mcc-table1, dp-table1, mcc-kp-200kPa, mcc-kp-200kPa-ocr1.5 (default all)");
  point->add_option("--material", o->material,
                    "run this material file instead of the built-in cases (from 100 kPa; a umat material "
                    "against its own Richardson-extrapolated fine solution, observed order reported)")
      ->check(CLI::ExistingFile);
  point->callback([o] {
    using namespace verification;
    WorkPrecisionOptions options;
    if (!o->increments.empty()) options.increments = o->increments;
    options.min_seconds = o->min_seconds;
    options.substep_tolerances = o->substep_tolerances;
    options.implicit_tolerances = o->implicit_tolerances;
    std::filesystem::create_directories(o->out);
    std::vector<WorkPrecisionRow> rows;
    // The Table 1 soils (MCC with constant E = 1 MPa) from 100 kPa, NC; then the Table 1 clay with
    // K = (1+e0)p/kappa (21x stiffer at 200 kPa) from 200 kPa, NC and OCR 1.5.
    struct Case {
      std::string label, file;
      bool pressure_dependent;
      double p_initial, ocr;
    };
    std::vector<Case> cases = {{"mcc-table1", "mcc-table1", false, 100e3, 1.0},
                               {"dp-table1", "dp-table1", false, 100e3, 1.0},
                               {"mcc-kp-200kPa", "mcc-table1", true, 200e3, 1.0},
                               {"mcc-kp-200kPa-ocr1.5", "mcc-table1", true, 200e3, 1.5}};
    if (!o->material.empty()) {
      if (!o->only.empty()) throw ParameterError("--case and --material exclude each other");
      cases = {{std::filesystem::path(o->material).stem().string(), o->material, false, 100e3, 1.0}};
    }
    std::vector<std::string> notes;
    for (const Case& c : cases) {
      if (!o->only.empty() && o->only != c.label) continue;
      Material material = o->material.empty()
                              ? table1_material(o->data.empty() ? data_dir().string() : o->data, c.file)
                              : load_material(c.file);
      if (c.pressure_dependent)
        material = with_edited_params(material, [](auto& params) {
          if constexpr (requires { params.elasticity; }) {
            params.elasticity = Elasticity::Kind::PressureDependent;
            params.elastic_pressure_floor = 1e3;
          }
        });
      const std::string name = c.label;
      // The stiff clay is where the driver's path error shows (docs/method/integrators.md); the Table 1 rows
      // stay as they were.
      WorkPrecisionOptions case_options = options;
      if (c.pressure_dependent) case_options.path_tolerances = o->path_tolerances;
      for (LoadPath path : {LoadPath::TriaxialDrained, LoadPath::TriaxialUndrained, LoadPath::Oedometer}) {
        PointTest test;  // to eps_a = 0.1
        test.path = path;
        test.p_initial = c.p_initial;
        test.ocr = c.ocr;
        const auto part = work_precision(name, material, test, case_options, [](const WorkPrecisionRow& r) {
          std::printf("%-11s %-19s %-30s %6d  err_q %.3e  err_p %.3e  %.3e s\n", r.material.c_str(),
                      r.path.c_str(), r.integrator.c_str(), r.increments, r.error_q, r.error_p,
                      r.cpu_seconds);
          std::fflush(stdout);
        }, &notes);
        rows.insert(rows.end(), part.begin(), part.end());
      }
    }
    std::ofstream csv(o->out + "/work_precision.csv");
    write_work_precision_csv(csv, rows);
    for (const std::string& note : notes) std::printf("%s\n", note.c_str());
    std::printf("wrote %s/work_precision.csv\n", o->out.c_str());
  });
  add_bench_collapse_command(*bench);
  add_bench_scaling_command(*bench);
}

}  // namespace soilsph::cli
