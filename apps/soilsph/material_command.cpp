// `soilsph material FILE`: validates a [material] table and prints the derived model constants.
#include <iostream>

#include "apps/soilsph/commands.h"
#include "constitutive/material.h"

namespace soilsph::cli {

void add_material_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("material", "Validate a [material] table and print the model's constants");
  auto path = std::make_shared<std::string>();
  cmd->add_option("FILE", *path, "TOML file with a [material] table")->required()->check(CLI::ExistingFile);
  cmd->callback([path] {
    const Material material = load_material(*path);
    std::cout << *path << ": " << model_name(material) << ", density " << density(material) << " kg/m^3\n";
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
  });
}

}  // namespace soilsph::cli
