// soilsph: constitutive-model verification and SPH soil-collapse simulation.
#include <iostream>

#include "apps/soilsph/commands.h"
#include "constitutive/parameters.h"

int main(int argc, char** argv) {
  CLI::App app{"soilsph: elastic-plastic soil models (Drucker-Prager, Modified Cam-Clay), their "
               "material-point verification, and SPH soil-collapse simulation"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "soilsph 0.1.0");
  soilsph::cli::add_material_command(app);
  soilsph::cli::add_stress_test_command(app);
  soilsph::cli::add_bench_command(app);
  soilsph::cli::add_point_command(app);
  soilsph::cli::add_verify_command(app);
  soilsph::cli::add_collapse_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const soilsph::ParameterError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
