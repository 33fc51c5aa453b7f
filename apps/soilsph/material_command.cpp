// `soilsph material FILE`: validates a [material] table and prints the derived model constants (a
// UMAT plug-in: its library and symbol found and one call made from the initial state); with
// --check-tangent, the model's tangent against central differences along a test path.
#include <cstdio>
#include <iostream>

#include "apps/soilsph/commands.h"
#include "apps/soilsph/range_validator.h"
#include "constitutive/material.h"
#include "verification/point_test.h"
#include "verification/tangent_check.h"

namespace soilsph::cli {

namespace {

struct TangentCheckOptions {
  bool enabled = false;
  std::string test = "triaxial-drained";
  double p_initial = 100e3;
  double strain_max = 0.05;
  int increments = 20;
  double tolerance = 1e-4;
};

/// Prints the largest relative error of each increment and of each component over the path;
/// returns whether every one is within the tolerance.
bool report_tangent_check(const Material& material, const TangentCheckOptions& o) {
  using namespace verification;
  PointTest test;
  try {
    test.path = parse_load_path(o.test);
  } catch (const std::invalid_argument& e) {
    throw ParameterError("--test " + o.test + ": " + e.what());
  }
  if (test.path == LoadPath::StrainPath) throw ParameterError("--test strain-path: use a built-in test here");
  test.p_initial = o.p_initial;
  test.strain_targets = {o.strain_max};
  test.increments = o.increments;
  const std::vector<TangentCheckRow> rows = check_tangent(material, programme_of(material, test));
  std::cout << "tangent check on " << o.test << " from p = " << o.p_initial << " Pa to strain "
            << o.strain_max << " in " << o.increments
            << " increments: the returned tangent T against central differences F of the "
            << "update, |T_ij - F_ij| / max|F| (Voigt 11, 22, 33, 12, 13, 23)\n";
  std::cout << "increment,max_relative_error,component\n";
  Mat6 worst = Mat6::Zero();
  for (const TangentCheckRow& row : rows) {
    Eigen::Index i = 0, j = 0;
    const double e = row.relative_error.maxCoeff(&i, &j);
    std::printf("%d,%.3e,%d%d\n", row.increment, e, static_cast<int>(i + 1), static_cast<int>(j + 1));
    worst = worst.cwiseMax(row.relative_error);
  }
  std::cout << "largest relative error of each component over the path:\n";
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) std::printf("%s%.1e", j ? " " : "  ", worst(i, j));
    std::printf("\n");
  }
  const bool within = worst.maxCoeff() <= o.tolerance;
  std::cout << (within ? "tangent agrees with central differences within "
                       : "TANGENT DIFFERS from central differences by more than ")
            << o.tolerance << '\n';
  return within;
}

}  // namespace

void add_material_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("material", "Validate a [material] table and print the model's constants");
  auto path = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>();
  auto check = std::make_shared<TangentCheckOptions>();
  cmd->add_option("FILE", *path, "TOML file with a [material] table (a scene file works too)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--material", *name,
                  "the material of a scene of named materials: its [materials.NAME] table")
      ->type_name("NAME");
  cmd->add_flag("--check-tangent", check->enabled,
                "compare the model's tangent (a UMAT's DDSDDE) with central differences of its update along "
                "--test; exit status 1 if they differ by more than --tangent-tolerance");
  auto* test = cmd->add_option("--test", check->test,
                               "with --check-tangent: triaxial-drained, triaxial-undrained, "
                               "oedometer or isotropic")
                   ->capture_default_str();
  auto* p_initial = cmd->add_option("--p-initial", check->p_initial,
                                    "with --check-tangent: initial isotropic "
                                    "effective stress, Pa (compression-positive)")
                        ->capture_default_str()
                        ->check(in_range(verification::point_limits::p_initial(), "Pa"));
  auto* strain_max =
      cmd->add_option("--strain-max", check->strain_max,
                      "with --check-tangent: target of the driven strain, compression-positive")
          ->capture_default_str()
          ->check(in_range(verification::point_limits::strain()));
  auto* increments = cmd->add_option("--increments", check->increments, "with --check-tangent: increments")
                         ->capture_default_str()
                         ->transform(whole_number_in(1, 100000));
  auto* tolerance = cmd->add_option("--tangent-tolerance", check->tolerance,
                                    "with --check-tangent: the largest relative error accepted")
                        ->capture_default_str()
                        ->check(in_range(Range::open(0.0, 1.0)));
  cmd->callback([path, name, check, test, p_initial, strain_max, increments, tolerance] {
    if (!check->enabled &&
        test->count() + p_initial->count() + strain_max->count() + increments->count() + tolerance->count() >
            0)
      throw ParameterError(
          "--test, --p-initial, --strain-max, --increments and --tangent-tolerance apply with "
          "--check-tangent only");
    const Material material = load_material(*path, *name);
    std::cout << *path << (name->empty() ? "" : " [materials." + *name + "]") << ": " << model_name(material)
              << ", density " << density(material) << " kg/m^3\n";
    std::visit([](const auto& m) { std::cout << m.describe_constants(); }, material);
    if (const double tau = viscoplastic_relaxation_time(material); tau > 0.0) {
      // What sets a viscoplastic deposit is the slow-flow viscosity G τ (docs/validation/resolution.md);
      // pressure-dependent G is given at two pressures.
      std::visit(
          [&](const auto& m) {
            const Elasticity& e = m.elasticity();
            const bool constant = e.kind() == Elasticity::Kind::Constant;
            std::cout << "  viscoplastic relaxation time tau = " << tau << " s: slow-flow viscosity G tau = ";
            if (constant) {
              std::cout << e.at(0.0).G * tau << " Pa s\n";
            } else {
              std::cout << e.at(1e3).G * tau << " Pa s at p = 1 kPa, " << e.at(1e5).G * tau
                        << " Pa s at p = 100 kPa\n";
            }
          },
          material);
    }
    if (check->enabled && !report_tangent_check(material, *check)) throw ExitCode{1};
  });
}

}  // namespace soilsph::cli
