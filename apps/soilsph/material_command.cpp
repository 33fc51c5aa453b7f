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
  });
}

}  // namespace soilsph::cli
