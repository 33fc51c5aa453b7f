// `soilsph material FILE`: validates a [material] table and prints the derived model constants.
#include <iostream>

#include "apps/soilsph/commands.h"
#include "constitutive/material.h"

namespace soilsph::cli {

namespace {
void describe(const LinearElastic& m) {
  const Moduli D = m.elasticity().at(0.0);
  std::cout << "  K = " << D.K << " Pa, G = " << D.G << " Pa\n";
}
void describe(const DruckerPrager& m) {
  const Moduli D = m.elasticity().at(0.0);
  std::cout << "  K = " << D.K << " Pa, G = " << D.G << " Pa\n"
            << "  alpha_phi = " << m.alpha_phi() << ", k_c = " << m.k_c() << " Pa (eq 19, plane strain)\n"
            << "  alpha_psi = " << m.alpha_psi() << " (the plastic potential's I1 coefficient, "
            << plastic_potential_name(m.params().plastic_potential) << ")\n";
}
void describe(const ModifiedCamClay& m) {
  std::cout << "  M = " << m.M() << " (eq 26), (1+e0)/(lambda-kappa) = " << m.hardening_exponent() << '\n';
}
}  // namespace

void add_material_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("material", "Validate a [material] table and print the model's constants");
  auto path = std::make_shared<std::string>();
  cmd->add_option("FILE", *path, "TOML file with a [material] table")->required()->check(CLI::ExistingFile);
  cmd->callback([path] {
    const Material material = load_material(*path);
    std::cout << *path << ": " << model_name(material) << ", density " << density(material) << " kg/m^3\n";
    std::visit([](const auto& m) { describe(m); }, material);
  });
}

}  // namespace soilsph::cli
