// UMAT plug-ins in the SPH collapse: the time step follows the stiffest particle's DDSDDE, and
// libsoilsph_umat.so loaded back through `model = "umat"` collapses a column as the built-in model does.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "sph/collapse.h"
#include "tests/common/material_toml.h"
#include "tests/sph/helpers.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {

const std::string kLibrary = SOILSPH_UMAT_LIBRARY;

/// The paper's column (4 cm x 6 cm, D-P of Table 1) at 4 mm, run to `end_time`.
std::string column(double end_time) {
  return "[scene]\ncolumn_width = 0.04\ncolumn_height = 0.06\nparticle_spacing = 0.004\nsmoothing_ratio = "
         "1.3\nend_time = " +
         std::to_string(end_time) +
         "\ngravity = 9.81\nwall_withdrawal = \"instant\"\nfloor_length = 0.25\n"
         "[numerics]\nartificial_stress = true\ncfl = 1.0\n";
}

/// Table 1's D-P through the exported library (docs/reference/umat-library.md: PROPS E, ν, φ, c, ψ).
const std::string kDruckerPragerUmat =
    "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" + kLibrary +
    "\"\nname = \"drucker-prager:implicit\"\nprops = [1.0e6, 0.3, 35.0, 0.0, "
    "0.0]\nstate_variables = 4\nthread_safe = true\n";

/// Table 1's MCC with pressure-dependent elasticity through the exported library (PROPS ν, φ, λ, κ,
/// e0, E = 0: pressure-dependent, the 1 kPa floor).
const std::string kCamClayUmat =
    "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" + kLibrary +
    "\"\nname = \"modified-cam-clay\"\nprops = [0.3, 35.0, 0.085, 0.019, 0.68, 0.0, "
    "0.0]\nstate_variables = 4\n";

Material material_from(const std::string& toml) {
  const toml::table root = toml::parse(toml);
  return read_material(TableReader(*root["material"].as_table(), "material.toml", "material"));
}

}  // namespace

TEST_CASE("A UMAT's wave speed is its DDSDDE's at each particle's state: the stiffest particle sets it",
          "[umat][sph]") {
  // Four particles of Table 1's MCC, lightly overconsolidated (OCR 2: the zero-increment call is
  // elastic), at 1, 10, 200 and 50 kPa.
  Particles p = test::lattice(2, 0.004, 2000.0);
  p.soil_count = p.size();
  const double pressures[] = {1e3, 1e4, 2e5, 5e4};
  for (std::size_t i = 0; i < 4; ++i) {
    p.state[i].stress = -pressures[i] * Mat3::Identity();
    p.state[i].pc = 2.0 * pressures[i];
    p.state[i].umat.statev[0] = 2.0 * pressures[i];  // STATEV(1) = p_c
    p.state[i].umat.increment = 1;                   // a state the UMAT has already updated
  }
  // The closed form at the stiffest particle, p = 200 kPa: K = (1 + e0) p / κ, G = 3K(1 − 2ν)/(2(1 + ν)),
  // c = √((K + 4G/3)/ρ).
  const double K = 1.68 * 2e5 / 0.019, G = 3.0 * K * 0.4 / 2.6;
  const double expected = std::sqrt((K + 4.0 / 3.0 * G) / 2000.0);
  const Material umat = material_from(kCamClayUmat);
  REQUIRE(stiffness_follows_state(umat));
  const double c = detail::largest_wave_speed(std::get<UmatModel>(umat), p, 0, 4);
  // The exported MCC's DDSDDE is a central difference of its update (relative error ~1e-8 here).
  CHECK(c == Approx(expected).epsilon(1e-6));
  // The built-in model agrees; the probe at zero stress (the 1 kPa floor) is 14 times slower.
  CHECK(c == Approx(largest_p_wave_speed(Elasticity::pressure_dependent(0.019, 0.68, 0.3, 1e3), p, 0, 4))
                 .epsilon(1e-6));
  CHECK(c > 10.0 * p_wave_speed(std::get<UmatModel>(umat).elasticity().at(0.0), 2000.0));
}

TEST_CASE("A UMAT column takes its first time step from its particles' geostatic state", "[umat][sph]") {
  // MCC through the UMAT, heavily overconsolidated (p_c = 100 kPa: the zero-increment call is
  // elastic), in a column whose base is at ρ g H = 12 kPa (10 times the 1 kPa floor of the probe at
  // zero stress): c is the P-wave speed of the closed form K = (1 + e0) max(p, 1 kPa)/κ at the particle of
  // the largest pressure, and the first step C h / c.
  const Scene scene = test::scene_from_text(
      column(1e-4) + kCamClayUmat + "initial_state = [1.0e5, 0.0, 0.0, 0.0]\n",
      {"scene.column_height=0.6", "scene.column_width=0.4", "scene.particle_spacing=0.02", "scene.floor_length=1.0"});
  Collapse collapse(scene);
  double p_max = 0.0;
  for (std::size_t i = 0; i < collapse.particles().soil_count; ++i)
    p_max = std::max(p_max, mean_pressure(collapse.particles().state[i].stress));
  REQUIRE(p_max > 5e3);
  const double K = 1.68 * p_max / 0.019, G = 3.0 * K * 0.4 / 2.6;
  const double c = std::sqrt((K + 4.0 / 3.0 * G) / 2000.0);
  const double h = 1.3 * 0.02;
  CHECK(collapse.run(ThreadTuner(1, false)).largest_time_step == Approx(1.0 * h / c).epsilon(1e-6));
}

TEST_CASE("libsoilsph_umat's D-P collapses the column as the built-in D-P does", "[umat][sph]") {
  // 0.3 s of the 4 mm column (176 particles, ~1300 steps: the column has fallen and spread). The two
  // runs differ only by round-off: the Voigt packing of the call, and c² from DDSDDE's λ + 2μ against
  // K + 4G/3 (a Δt a few ulp apart). A dissipative flow carries such differences without growing
  // them to anything a deposit can show: positions within 1e-9 m (2.5e-7 spacings), stresses within
  // 1e-6 of the largest.
  const Scene builtin_scene = test::scene_from_text(column(0.3) + fixtures::kDruckerPragerToml);
  const Scene umat_scene = test::scene_from_text(column(0.3) + kDruckerPragerUmat);
  Collapse builtin(builtin_scene), umat(umat_scene);
  const RunStatistics a = builtin.run(ThreadTuner(1, false)), b = umat.run(ThreadTuner(1, false));
  CHECK(a.steps == b.steps);
  const Particles &pa = builtin.particles(), &pb = umat.particles();
  REQUIRE(pa.soil_count == pb.soil_count);
  double position = 0.0, stress = 0.0, largest_stress = 0.0;
  for (std::size_t i = 0; i < pa.soil_count; ++i) {
    position = std::max({position, std::abs(pa.x[i] - pb.x[i]), std::abs(pa.y[i] - pb.y[i])});
    stress = std::max(stress, (pa.state[i].stress - pb.state[i].stress).cwiseAbs().maxCoeff());
    largest_stress = std::max(largest_stress, pa.state[i].stress.cwiseAbs().maxCoeff());
  }
  CAPTURE(position, stress, largest_stress, builtin.deposit().runout_m, umat.deposit().runout_m);
  CHECK(position < 1e-9);
  CHECK(stress < 1e-6 * largest_stress);
  CHECK(umat.deposit().runout_m == Approx(builtin.deposit().runout_m).margin(1e-9));
  // The UMAT's state variables were carried: STATEV(2), the accumulated plastic strain, is the
  // built-in model's.
  double plastic = 0.0, largest_plastic = 0.0;
  for (std::size_t i = 0; i < pa.soil_count; ++i) {
    plastic = std::max(plastic, std::abs(pa.state[i].plastic_shear_strain - pb.state[i].umat.statev[1]));
    largest_plastic = std::max(largest_plastic, pa.state[i].plastic_shear_strain);
  }
  CHECK(largest_plastic > 0.01);
  CHECK(plastic < 1e-6 * largest_plastic);
}
