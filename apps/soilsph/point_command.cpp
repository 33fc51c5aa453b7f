// `soilsph point MATERIAL.toml --test NAME ...`: one material-point test (triaxial, oedometer,
// isotropic or a strain-path file), or `soilsph point PROGRAMME.toml`: a laboratory programme
// (verification/programme/programme_file.h); written as a compression-positive CSV whose comment
// header records what produced it.
#include <fstream>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/pressure_option.h"
#include "apps/soilsph/range_validator.h"
#include "constitutive/material_description.h"
#include "constitutive/parameters.h"
#include "soilsph/version.h"
#include "verification/driver/rate_independence.h"
#include "verification/paths/strain_path_csv.h"
#include "verification/point_test.h"
#include "verification/programme/programme_file.h"

namespace soilsph::cli {

namespace {
namespace limits = verification::point_limits;

struct PointOptions {
  std::string material_path;
  std::string material_name;  ///< a scene's [materials.NAME]; empty: the [material] table
  std::string test;  ///< required unless the file is a programme
  std::string strain_path;
  double p_initial = 100e3;
  double ocr = 1.0;
  std::string strain_max = "0.1";  ///< comma-separated targets, checked by list_in_range
  int increments = 100;
  std::string integrator;       ///< empty: the material's `integrator` key
  double path_tolerance = 0.0;  ///< driver sub-steps (verification/driver/path_substeps.h); 0: off
  std::string out;
  std::vector<std::string> overrides;
  std::string tangent;  ///< a umat material's Newton tangent; empty: DDSDDE
};

bool is_umat(const Material& material) { return std::holds_alternative<UmatModel>(material); }

/// A umat material with the Newton tangent of --tangent; a built-in model refuses the option, and a
/// umat material refuses --integrator (it runs its own update).
Material with_tangent_option(const PointOptions& o, const Material& material) {
  if (!is_umat(material)) {
    if (!o.tangent.empty())
      throw ParameterError("--tangent applies to a umat material only (" + std::string(model_name(material)) +
                           " uses its own consistent or finite-difference tangent)");
    return material;
  }
  if (!o.integrator.empty())
    throw ParameterError("--integrator " + o.integrator +
                         ": a umat material runs its own update (no integrator of soilsph's, no CVODE reference)");
  return with_edited_params(material, [&o](auto& params) {
    if constexpr (requires { params.tangent; })
      params.tangent = o.tangent == kUmatTangentNames[1] ? UmatTangent::FiniteDifference : UmatTangent::Ddsdde;
  });
}

/// What a umat material's Newton iterations used, for the CSV header and a note on stderr.
std::string umat_tangent_report(const Material& material) {
  const auto* umat = std::get_if<UmatModel>(&material);
  if (!umat) return "";
  if (umat->params().tangent == UmatTangent::FiniteDifference)
    return "Newton tangent: central differences of the UMAT's update (--tangent finite-difference)";
  const long fallbacks = umat->fallback_count();
  return "Newton tangent: the UMAT's DDSDDE" +
         (fallbacks == 0 ? std::string()
                         : "; unusable (not finite or all zero) in " + std::to_string(fallbacks) +
                               " calls, where central differences of the update were used");
}

/// The [material] table of the file (or the scene's [materials.NAME] of --material) after the --set
/// overrides, which may only address it.
Material load_point_material(const PointOptions& o) {
  toml::table root = parse_toml_file(o.material_path);
  const std::string table_name = material_table_name(o.material_name);
  for (const std::string& assignment : o.overrides) {
    const std::size_t dot = assignment.find('.');
    if (dot < assignment.find('=') && !assignment.starts_with(table_name + "."))
      throw ParameterError("--set " + assignment + ": soilsph point reads only the [" + table_name +
                           "] table (use --set " + table_name + ".KEY=VALUE)");
    apply_override(root, assignment);
  }
  const toml::table& table = material_table(root, o.material_path, o.material_name);
  const Material material = blaming_overrides(
      o.overrides, [&] { return read_material(TableReader(table, o.material_path, table_name)); });
  warn_if_rate_dependent(material, o.material_path);
  return with_tangent_option(o, material);
}

/// --test and --strain-path resolved: `--test strain-path:FILE` is a shorthand for
/// `--test strain-path --strain-path FILE`. Returns the test's name and the strain-path file.
std::pair<std::string, std::string> test_and_strain_path(const PointOptions& o) {
  if (!o.test.starts_with("strain-path:")) return {o.test, o.strain_path};
  if (!o.strain_path.empty()) throw ParameterError("--strain-path given twice (also in --test)");
  return {"strain-path", o.test.substr(o.test.find(':') + 1)};
}

/// The test the options describe; ParameterError naming the option for a misuse.
verification::PointTest point_test(const PointOptions& o, bool legs_given) {
  using namespace verification;
  PointTest test;
  const auto [name, strain_path] = test_and_strain_path(o);
  try {
    test.path = parse_load_path(name);
  } catch (const std::invalid_argument& e) {
    throw ParameterError("--test " + name + ": " + e.what());
  }
  if (test.path == LoadPath::StrainPath) {
    if (strain_path.empty()) throw ParameterError("--test strain-path needs --strain-path FILE");
    if (legs_given)
      throw ParameterError(
          "--strain-max and --increments do not apply to --test strain-path (one "
          "increment per row of the file)");
    StrainPath rows = read_strain_path_file(strain_path);
    test.strain_increments = std::move(rows.increments);
    test.strain_increment_sources = std::move(rows.sources);
  } else if (!strain_path.empty()) {
    throw ParameterError("--strain-path applies to --test strain-path only");
  }
  test.p_initial = o.p_initial;
  test.ocr = o.ocr;
  test.strain_targets = split_numbers(o.strain_max);
  test.increments = o.increments;
  test.path_tolerance = o.path_tolerance;
  return test;
}

/// The integrator that runs: --integrator (a scheme, which replaces the material's key, or cvode),
/// else the material's `integrator` key.
std::string integrator_to_run(const PointOptions& o, const Material& material) {
  if (!o.integrator.empty()) return o.integrator;
  return std::visit(
      [](const auto& model) -> std::string {
        if constexpr (requires { model.integrator(); })
          return std::string(integrator_name(model.integrator()));
        else
          return "implicit";  // linear elasticity: every scheme is the elastic update
      },
      material);
}

/// How messages and the CSV name the integrator: the option, or the material's key.
std::string integrator_label(const PointOptions& o, const std::string& integrator) {
  return o.integrator.empty() ? "integrator " + integrator + " (the material's)"
                              : "--integrator " + integrator;
}

/// A name given with --integrator (an empty one too: it is not "the material's key").
void check_integrator(const std::string& name) {
  std::string allowed;
  for (std::string_view scheme : kIntegratorNames) {
    if (name == scheme) return;
    allowed += std::string(scheme) + ", ";
  }
  if (name == verification::kReferenceIntegrator) return;
  throw ParameterError("--integrator " + (name.empty() ? std::string("\"\"") : name) +
                       ": unknown integrator (allowed: " + allowed +
                       std::string(verification::kReferenceIntegrator) + ")");
}

/// The comment lines after the conventions line: what produced the curve, enough to run it again.
/// `material_source` is the material's file; `test` the test or programme in words.
std::vector<std::string> provenance(const PointOptions& o, const std::string& material_source,
                                    const Material& material, const std::string& integrator,
                                    const std::string& test) {
  using namespace verification;
  const bool reference = integrator == kReferenceIntegrator;
  const Material used = reference ? material : with_integrator(material, parse_integrator(integrator));
  std::vector<std::string> lines = {
      std::string("soilsph ") + kVersion,
      "command: " + invocation(),
      "material: " + material_source + (o.overrides.empty() ? "" : " with --set") + ": " + describe_material(used),
      is_umat(material) ? "integrator: the UMAT's own update (" + umat_tangent_report(material) + ")"
                        : "integrator: " + integrator +
                              (reference ? " (the CVODE reference; the material's integrator key is not used)"
                               : o.integrator.empty() ? " (the material's integrator key)"
                                                      : ""),
      test,
  };
  // Only when used, so that a run without it writes the plain header.
  if (o.path_tolerance > 0.0)
    lines.push_back("driver sub-steps: path_tolerance = " + exact_number(o.path_tolerance) +
                    " (each increment with stress-imposed components split by step doubling until its "
                    "estimated error <= path_tolerance; one row per requested increment)");
  if (const auto line = triaxial_failure_line(material))  // for plots, whichever the model
    lines.push_back("failure line (triaxial compression): q = slope p' + intercept; slope = " +
                    exact_number(line->slope) + "; intercept = " + exact_number(line->intercept) + " Pa");
  return lines;
}

void write(const PointOptions& o, const verification::PointCurve& curve,
           const std::vector<std::string>& comments) {
  for (const std::string& line : comments)
    if (line.find("unusable (not finite or all zero)") != std::string::npos) std::cerr << "note: " << line << '\n';
  if (o.out.empty()) {
    verification::write_point_csv(std::cout, curve, comments);
    return;
  }
  std::ofstream file(o.out);
  if (!file) throw std::runtime_error(o.out + ": cannot open for writing");
  verification::write_point_csv(file, curve, comments);
  file.flush();
  if (!file) throw std::runtime_error(o.out + ": write failed");
}

/// Runs `programme` and writes its curve with the comment lines `comments()`, turning its failures into the
/// command's errors: input errors (exit 2) and run failures naming the material, model and integrator (exit
/// 1). A run stopped at the soil's strength writes the curve up to there, the reason its last
/// comment line, before it fails.
template <class Comments>
void run_and_write(const PointOptions& o, const Material& material, const std::string& source,
                   const verification::Programme& programme, const std::string& integrator,
                   const Comments& comments) {
  const auto run_failure = [&](const std::exception& e) {
    return std::runtime_error(source + " (" + std::string(model_name(material)) + ", " +
                              (is_umat(material) ? std::string("its own update") : integrator_label(o, integrator)) +
                              "): " + e.what());
  };
  verification::PointCurve curve;
  try {
    curve = verification::run_programme(material, programme, integrator);
  } catch (const ParameterError&) {
    throw;
  } catch (const std::invalid_argument& e) {  // the test's inputs: out of range, a leg of zero length
    throw ParameterError(e.what());
  } catch (const verification::StrengthReachedError& e) {
    std::vector<std::string> lines = comments();
    lines.push_back(std::string("stopped: ") + e.what());
    write(o, e.curve, lines);
    throw run_failure(e);
  } catch (const std::runtime_error& e) {  // a run that failed or lost meaning, at the named increment
    throw run_failure(e);
  }
  write(o, curve, comments());
}

void run_programme_file(const PointOptions& o, bool options_given) {
  if (!o.material_name.empty())
    throw ParameterError("--material " + o.material_name + ": " + o.material_path +
                         " is a programme: its `material` key names the material");
  if (options_given)
    throw ParameterError(
        o.material_path +
        " is a programme: --test, --strain-path, --p-initial, --ocr, --strain-max and --increments "
        "do not apply (its [initial] table and [[leg]] tables say it all)");
  verification::ProgrammeFile file = verification::read_programme_file(o.material_path, o.overrides);
  file.material = with_tangent_option(o, file.material);
  const std::string integrator = integrator_to_run(o, file.material);
  PointOptions used = o;  // the file's path_tolerance unless --path-tolerance is given; CVODE needs none
  if (o.path_tolerance == 0.0) used.path_tolerance = file.programme.path_tolerance;
  if (integrator == verification::kReferenceIntegrator) used.path_tolerance = 0.0;
  file.programme.path_tolerance = used.path_tolerance;
  run_and_write(used, file.material, o.material_path, file.programme, integrator, [&] {
    return provenance(used, file.material_source, file.material, integrator,
                      "programme: " + file.description);
  });
}

void run(const PointOptions& o, bool legs_given, bool test_options_given) {
  if (o.path_tolerance > 0.0 && o.integrator == verification::kReferenceIntegrator)
    throw ParameterError(
        "--path-tolerance does not apply to --integrator cvode (the reference holds the "
        "imposed stresses throughout)");
  if (verification::is_programme_file(o.material_path))
    return run_programme_file(o, legs_given || test_options_given);
  if (o.test.empty()) {
    parse_toml_file(o.material_path);  // a programme with a syntax error: its file, line and column
    throw ParameterError(o.material_path +
                         ": no [[leg]] table, so not a programme file (docs/reference/programmes.md); "
                         "a material file needs --test");
  }
  const verification::PointTest test = point_test(o, legs_given);
  const Material material = load_point_material(o);
  if (test.ocr != 1.0 && !has_preconsolidation(material))
    throw ParameterError("--ocr " + format_number(test.ocr) + ": OCR applies to " +
                         preconsolidation_models() + " only (" + std::string(model_name(material)) +
                         " has no preconsolidation pressure)");
  const std::string integrator = integrator_to_run(o, material);
  verification::Programme programme;
  try {
    programme = verification::programme_of(material, test);
  } catch (const std::invalid_argument& e) {
    // The options' own ranges are checked by CLI11; what is left is a strain path's row (which
    // names its file and line) or the targets together (a leg of zero length).
    if (test.path == verification::LoadPath::StrainPath) throw ParameterError(e.what());
    throw ParameterError("--strain-max " + o.strain_max + ": " + e.what());
  }
  const std::string source =
      o.material_name.empty() ? o.material_path : o.material_path + " [materials." + o.material_name + "]";
  run_and_write(o, material, source, programme, integrator, [&] {
    return provenance(o, source, material, integrator,
                      "test: " + describe_test(test, test_and_strain_path(o).second));
  });
}

}  // namespace

void add_point_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("point",
                                 "Run a material-point test (triaxial, oedometer, isotropic, strain path) or "
                                 "a programme file; write its CSV");
  auto o = std::make_shared<PointOptions>();
  cmd->add_option("FILE", o->material_path,
                  "a programme file ([initial] and [[leg]] tables; soilsph examples lists the shipped ones), or a "
                  "TOML file with a [material] table (a scene file works too) run with --test")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--material", o->material_name,
                  "the material of a scene of named materials to test: its [materials.NAME] table")
      ->type_name("NAME");
  auto* test = cmd->add_option("--test", o->test,
                               "triaxial-drained, triaxial-undrained, oedometer, isotropic, or strain-path "
                               "(with --strain-path FILE, or as strain-path:FILE); not with a programme");
  auto* strain_path =
      cmd->add_option(
             "--strain-path", o->strain_path,
             "CSV of strain increments d_xx,d_yy,d_zz,d_xy,d_yz,d_xz (tension-positive), one per row")
          ->check(CLI::ExistingFile);
  auto* p_initial = cmd->add_option("--p-initial", o->p_initial,
                                    "initial isotropic effective stress, compression-positive, with a unit "
                                    "(100kPa, 0.1MPa) or in Pa")
                        ->capture_default_str()
                        ->transform(pressure_in(limits::p_initial()))
                        ->type_name("PRESSURE");
  auto* ocr = cmd->add_option("--ocr", o->ocr, "overconsolidation ratio, MCC p_c0 = OCR * p_initial (MCC only)")
      ->capture_default_str()
      ->check(in_range(limits::ocr()));
  auto* strain_max = cmd->add_option("--strain-max", o->strain_max,
                                     "targets of the driven strain, compression-positive, one leg each "
                                     "(axial; volumetric for isotropic), e.g. 0.1,0.05,0.15")
                         ->capture_default_str()
                         ->check(list_in_range(limits::strain()));
  auto* increments = cmd->add_option("--increments", o->increments, "increments per leg")
                         ->capture_default_str()
                         ->transform(whole_number_in(1, limits::kMaxIncrements));
  std::string integrators;
  for (std::string_view name : kIntegratorNames) integrators += std::string(name) + ", ";
  auto* integrator = cmd->add_option(
      "--integrator", o->integrator,
      "stress integrator: " + integrators +
          "or cvode (the reference); replaces the material's (default: the material's integrator key)");
  cmd->add_option("--path-tolerance", o->path_tolerance,
                  "driver sub-steps: split each increment with stress-imposed components (drained/undrained "
                  "triaxial, programme legs) until its step-doubling error estimate is <= this, relative "
                  "(default 0: off, one solve per increment)")
      ->check(in_range(limits::path_tolerance()));
  cmd->add_option("--tangent", o->tangent,
                  "a umat material's Newton tangent: ddsdde (the UMAT's, default; central differences where it is "
                  "unusable, reported) or finite-difference")
      ->check(CLI::IsMember({std::string(kUmatTangentNames[0]), std::string(kUmatTangentNames[1])}));
  cmd->add_option("--out", o->out, "output CSV (default: standard output)");
  cmd->add_option("--set", o->overrides,
                  "override a material key, e.g. --set material.friction_angle=30, or --set "
                  "materials.NAME.friction_angle=30 with --material NAME (repeatable)");
  cmd->callback([o, strain_max, increments, test, strain_path, p_initial, ocr, integrator] {
    if (integrator->count() > 0) check_integrator(o->integrator);
    run(*o, strain_max->count() + increments->count() > 0,
        test->count() + strain_path->count() + p_initial->count() + ocr->count() > 0);
  });
}

}  // namespace soilsph::cli
