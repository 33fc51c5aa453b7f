#pragma once
/// @file
/// Each subcommand of `soilsph` lives in its own file and registers itself on the root app here.
/// A subcommand is thin: it parses options and calls the libraries.
#include <CLI/CLI.hpp>

namespace soilsph::cli {

void add_material_command(CLI::App& app);
void add_collapse_command(CLI::App& app);

}  // namespace soilsph::cli
