#pragma once
// The paper's elastic soil (E = 1 MPa, ν = 0.3, ρ = 2000 kg/m³) as a [material] TOML table, for the
// tests that build scenes and programmes from text (a table, so it goes after the top-level keys).
#include <string>

namespace soilsph::fixtures {

inline const std::string kLinearElasticToml = R"(
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
)";

}  // namespace soilsph::fixtures
