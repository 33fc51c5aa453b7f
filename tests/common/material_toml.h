#pragma once
// The paper's soils as [material] TOML tables, for the tests that build scenes, materials and
// programmes from text (a table, so it goes after the top-level keys): elastic (E = 1 MPa, ν = 0.3,
// ρ = 2000 kg/m³), Drucker–Prager with Table 1's φ = 35°, c = 0, ψ = 0, and Table 1's Modified
// Cam-Clay (its elasticity by default; keys appended after it stay in [material]).
#include <string>

namespace soilsph::fixtures {

inline const std::string kLinearElasticToml = R"(
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
)";

inline const std::string kDruckerPragerToml = R"(
[material]
model = "drucker-prager"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 35.0
cohesion = 0.0
dilatancy_angle = 0.0
)";

inline const std::string kCamClayToml = R"(
[material]
model = "modified-cam-clay"
density = 2000.0
poisson_ratio = 0.3
friction_angle = 35.0
compression_index = 0.085
swelling_index = 0.019
initial_void_ratio = 0.68
)";

}  // namespace soilsph::fixtures
