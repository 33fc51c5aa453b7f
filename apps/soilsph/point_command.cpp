// `soilsph point MATERIAL.toml --test NAME ...`: one material-point test (triaxial, oedometer,
// isotropic or a strain-path file) written as a compression-positive CSV.
#include <fstream>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "constitutive/parameters.h"
#include "verification/paths/strain_path_csv.h"
#include "verification/point_test.h"

namespace soilsph::cli {

namespace {

struct PointOptions {
  std::string material_path;
  std::string test = "triaxial-drained";
  std::string strain_path;
  double p_initial = 100e3;
  double ocr = 1.0;
  std::vector<double> strain_max = {0.1};
  int increments = 100;
  std::string integrator{kDefaultPointIntegrator};
  std::string out;
  std::vector<std::string> overrides;
};

Material load_point_material(const PointOptions& o) {
  toml::table root = parse_toml_file(o.material_path);
  for (const std::string& assignment : o.overrides) apply_override(root, assignment);
  const toml::table* table = root["material"].as_table();
  if (!table) throw ParameterError(o.material_path + ": no [material] table");
  return read_material(TableReader(*table, o.material_path, "material"));
}

void run(const PointOptions& o, bool legs_given) {
  using namespace verification;
  verification::PointTest test;
  // `--test strain-path:FILE` is accepted as a shorthand for `--test strain-path --strain-path FILE`.
  std::string name = o.test, strain_path = o.strain_path;
  if (const auto colon = name.find(':'); colon != std::string::npos && name.starts_with("strain-path:")) {
    if (!strain_path.empty()) throw std::invalid_argument("--strain-path given twice (also in --test)");
    strain_path = name.substr(colon + 1);
    name = "strain-path";
  }
  test.path = parse_load_path(name);
  if (test.path == LoadPath::StrainPath) {
    if (strain_path.empty()) throw std::invalid_argument("--test strain-path needs --strain-path FILE");
    if (legs_given)
      throw std::invalid_argument(
          "--strain-max and --increments do not apply to --test strain-path (one "
          "increment per row of the file)");
    test.strain_increments = read_strain_path_file(strain_path);
  } else if (!strain_path.empty()) {
    throw std::invalid_argument("--strain-path applies to --test strain-path only");
  }
  test.p_initial = o.p_initial;
  test.ocr = o.ocr;
  test.strain_targets = o.strain_max;
  test.increments = o.increments;
  const Material material = load_point_material(o);
  const PointCurve curve = run_point_test(material, test, o.integrator);
  if (o.out.empty()) {
    write_point_csv(std::cout, curve);
    return;
  }
  std::ofstream file(o.out);
  if (!file) throw std::runtime_error(o.out + ": cannot open for writing");
  write_point_csv(file, curve);
  if (!file) throw std::runtime_error(o.out + ": write failed");
}

}  // namespace

void add_point_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "point", "Run a material-point test (triaxial, oedometer, isotropic, strain path) and write its CSV");
  auto o = std::make_shared<PointOptions>();
  cmd->add_option("MATERIAL", o->material_path, "TOML file with a [material] table (a scene file works too)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--test", o->test,
                  "triaxial-drained, triaxial-undrained, oedometer, isotropic, or strain-path "
                  "(with --strain-path FILE, or as strain-path:FILE)")
      ->required();
  cmd->add_option("--strain-path", o->strain_path,
                  "CSV of strain increments d_xx,d_yy,d_zz,d_xy,d_yz,d_xz (tension-positive), one per row")
      ->check(CLI::ExistingFile);
  cmd->add_option("--p-initial", o->p_initial,
                  "initial isotropic effective stress, Pa (compression-positive)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--ocr", o->ocr, "overconsolidation ratio, MCC p_c0 = OCR * p_initial (>= 1)")
      ->capture_default_str();
  auto* strain_max = cmd->add_option("--strain-max", o->strain_max,
                                     "targets of the driven strain, compression-positive, one leg each "
                                     "(axial; volumetric for isotropic), e.g. 0.1,0.05,0.15")
                         ->delimiter(',')
                         ->capture_default_str();
  auto* increments = cmd->add_option("--increments", o->increments, "increments per leg")
                         ->capture_default_str()
                         ->check(CLI::PositiveNumber);
  std::string integrators;
  for (std::string_view name : kIntegratorNames) integrators += std::string(name) + ", ";
  cmd->add_option("--integrator", o->integrator,
                  "stress integrator: " + integrators + "or cvode (the reference)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "output CSV (default: standard output)");
  cmd->add_option("--set", o->overrides,
                  "override a material key, e.g. --set material.friction_angle=30 (repeatable)");
  cmd->callback([o, strain_max, increments] { run(*o, strain_max->count() + increments->count() > 0); });
}

}  // namespace soilsph::cli
