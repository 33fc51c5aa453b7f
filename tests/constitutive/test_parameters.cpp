// Input validation: every bad value names the file, the key and the allowed range.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <fstream>

#include "constitutive/material_description.h"
#include "../common/material_toml.h"
#include "helpers.h"

using namespace soilsph;
using Catch::Matchers::Contains;

namespace {
Material from_text(const std::string& text) {
  const toml::table root = toml::parse(text);
  return read_material(TableReader(*root["material"].as_table(), "case.toml", "material"));
}
const std::string& kDruckerPrager = fixtures::kDruckerPragerToml;
const std::string& kCamClay = fixtures::kCamClayToml;
std::string replace(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}
}  // namespace

TEST_CASE("the shipped Table 1 materials load", "[parameters]") {
  const Material dp = load_material(SOILSPH_SOURCE_DIR "/data/materials/dp-table1.toml");
  const Material mcc = load_material(SOILSPH_SOURCE_DIR "/data/materials/mcc-table1.toml");
  CHECK(model_name(dp) == "drucker-prager");
  CHECK(model_name(mcc) == "modified-cam-clay");
  CHECK(density(mcc) == 2000.0);
  CHECK(std::get<ModifiedCamClay>(mcc).params().swelling_index == 0.019);
  const Material mc = load_material(SOILSPH_SOURCE_DIR "/data/materials/mc-table1.toml");
  CHECK(model_name(mc) == "mohr-coulomb");
  CHECK(std::get<MohrCoulomb>(mc).params().friction_angle == std::get<DruckerPrager>(dp).params().friction_angle);
  CHECK(!std::get<MohrCoulomb>(mc).has_tension_cutoff());
}

TEST_CASE("invalid parameters are rejected with file, key and range", "[parameters]") {
  CHECK_NOTHROW(from_text(kDruckerPrager));
  CHECK_NOTHROW(from_text(kCamClay));
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {replace(kDruckerPrager, "young_modulus = 1.0e6", "young_modulus = -5.0"),
       "case.toml: [material] young_modulus = -5 is out of range (allowed: 1 <= value <= 1e12 Pa)"},
      {replace(kDruckerPrager, "young_modulus = 1.0e6", "young_modulus = 1e24"),
       "[material] young_modulus = 1e24 is out of range (allowed: 1 <= value <= 1e12 Pa)"},
      // Below 1 Pa an update's stiffness products reach subnormal numbers (E = 1e-300 lost an undrained
      // path's volume constraint), and E = 5e-324 made G = 0.
      {replace(kDruckerPrager, "young_modulus = 1.0e6", "young_modulus = 5e-324"),
       "[material] young_modulus = 4.94066e-324 is out of range (allowed: 1 <= value <= 1e12 Pa)"},
      {kCamClay + "elasticity = \"constant\"\nyoung_modulus = 0.999\n",
       "[material] young_modulus = 0.999 is out of range (allowed: 1 <= value <= 1e12 Pa)"},
      {kCamClay + "implicit_tolerance = 1e-30\n",
       "[material] implicit_tolerance = 1e-30 is out of range (allowed: value = 0 or 1e-12 <= value <= "
       "0.01)"},
      {replace(kDruckerPrager, "poisson_ratio = 0.3", "poisson_ratio = 0.5"),
       "[material] poisson_ratio = 0.5 is out of range (allowed: -1 < value < 0.5)"},
      {replace(kDruckerPrager, "friction_angle = 35.0", "friction_angle = 90"),
       "[material] friction_angle = 90 is out of range (allowed: 0 < value < 90 degrees)"},
      {replace(kDruckerPrager, "cohesion = 0.0", "cohesion = -1.0"),
       "[material] cohesion = -1 is out of range (allowed: 0 <= value <= 1e12 Pa)"},
      {replace(kDruckerPrager, "cohesion = 0.0", "cohesion = 1e308"),
       "[material] cohesion = 1e308 is out of range (allowed: 0 <= value <= 1e12 Pa)"},
      {kCamClay + "elastic_pressure_floor = 1e13\n",
       "[material] elastic_pressure_floor = 1e13 is out of range (allowed: 0 < value <= 1e12 Pa)"},
      {replace(kDruckerPrager, "dilatancy_angle = 0.0", "dilatancy_angle = 40.0"),
       "[material] dilatancy_angle = 40 is out of range (allowed: 0 <= value <= 35 degrees)"},
      {kDruckerPrager + "dilatancy_cutoff = 0\n",
       "[material] dilatancy_cutoff = 0 is out of range (allowed: 0 < value <= 1)"},
      {kDruckerPrager + "dilatancy_cutoff = 1.5\n",
       "[material] dilatancy_cutoff = 1.5 is out of range (allowed: 0 < value <= 1)"},
      {replace(kDruckerPrager, "density = 2000.0", "density = 0.0"),
       "[material] density = 0 is out of range (allowed: 0 < value kg/m^3)"},
      {replace(kCamClay, "swelling_index = 0.019", "swelling_index = 0.1"),
       "[material] swelling_index = 0.1 is out of range (allowed: 0 < value < 0.085)"},
      {replace(kCamClay, "initial_void_ratio = 0.68", "initial_void_ratio = 0"),
       "[material] initial_void_ratio = 0 is out of range (allowed: 0 < value)"},
      {replace(kCamClay, "compression_index = 0.085", "compression_index = \"high\""),
       "[material] compression_index: must be a number"},
      {replace(kCamClay, "density = 2000.0\n", ""), "[material] density: is missing"},
      {replace(kCamClay, "model = \"modified-cam-clay\"", "model = \"cam-clay\""),
       "[material] model = \"cam-clay\" is not allowed (allowed: \"linear-elastic\", \"drucker-prager\", "
       "\"modified-cam-clay\", \"mohr-coulomb\", \"umat\")"},
      {kDruckerPrager + "integrator = \"rk4\"\n", "[material] integrator = \"rk4\" is not allowed"},
      {kCamClay + "elasticity = \"nonlinear\"\n", "[material] elasticity = \"nonlinear\" is not allowed"},
      {kDruckerPrager + "plastic_potential = \"eq20\"\n",
       "case.toml: [material] plastic_potential = \"eq20\" is not allowed (allowed: \"matched\", "
       "\"paper-eq20\")"},
      {kDruckerPrager + "plastic_potential = 20\n", "case.toml: [material] plastic_potential"},
      {kCamClay + "elasticity = \"constant\"\n", "[material] young_modulus: is missing"},
      {kCamClay + "viscoplastic_relaxation_time = -1e-4\n",
       "[material] viscoplastic_relaxation_time = -0.0001 is out of range (allowed: 0 <= value <= 1000 s)"},
      {kDruckerPrager + "viscoplastic_relaxation_time = 1e4\n",
       "[material] viscoplastic_relaxation_time = 10000 is out of range (allowed: 0 <= value <= 1000 s)"},
      {kDruckerPrager + "frictoin_angle = 30.0\n",
       "case.toml: [material] frictoin_angle: is not a known key (did you mean \"friction_angle\"?)"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK_THROWS_WITH(from_text(c.text), Contains(c.message));
    CHECK_THROWS_AS(from_text(c.text), ParameterError);
  }
}

// Keys within their ranges that combine into a derived constant that is infinite or zero. Each
// expected value is what IEEE arithmetic makes of the formula: 1 + 1e308 over λ − κ = 0.066
// overflows, sin and tan of 5e-324 degrees (9e-326 rad) are 0. (E = 5e-324 made G = 0 until E ≥ 1 Pa.)
TEST_CASE("derived constants that are not finite and positive are rejected, naming the key", "[parameters]") {
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {replace(kDruckerPrager, "friction_angle = 35.0", "friction_angle = 5e-324"),
       "[material] friction_angle = 4.94066e-324 gives alpha_phi = tan(phi)/sqrt(9 + 12 tan^2(phi)) (eq 19) "
       "= "
       "0, which must be finite and > 0"},
      // φ = 1e-300 degrees: α_φ = 5.8e-303 > 0, but the apex 3c/tan φ = 3e7 Pa / 1.7e-302 overflows.
      {replace(replace(kDruckerPrager, "friction_angle = 35.0", "friction_angle = 1e-300"), "cohesion = 0.0",
               "cohesion = 1e7"),
       "[material] cohesion = 1e7 gives the apex's I1 = 3c/tan(phi) = inf Pa, which must be finite and >= 0"},
      {replace(kCamClay, "initial_void_ratio = 0.68", "initial_void_ratio = 1e308"),
       "[material] initial_void_ratio = 1e308 gives (1+e0)/(lambda-kappa) (eq 27) = inf, which must be "
       "finite"},
      // MCC's M = 6 sin(phi)/(3 - sin(phi)) (eq 26) vanishes with phi: refused below 1 degree.
      {replace(kCamClay, "friction_angle = 35.0", "friction_angle = 5e-324"),
       "[material] friction_angle = 4.94066e-324 is out of range (allowed: 1 <= value < 90 degrees)"},
      {replace(kCamClay, "friction_angle = 35.0", "friction_angle = 0.999"),
       "[material] friction_angle = 0.999 is out of range"},
      // κ/(1+e0) = 1e-310/1.68 is subnormal, so K at the 1 kPa floor is 1e3/6e-311 = inf.
      {replace(kCamClay, "swelling_index = 0.019", "swelling_index = 1e-310"),
       "[material] swelling_index = 1e-310 gives K = p_floor (1+e0)/kappa at the elastic_pressure_floor = "
       "inf Pa"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK_THROWS_WITH(from_text(c.text), Contains(c.message));
    CHECK_THROWS_AS(from_text(c.text), ParameterError);
  }
  CHECK_NOTHROW(from_text(replace(kCamClay, "friction_angle = 35.0", "friction_angle = 1.0")));
  // The largest values of each range still give usable constants.
  CHECK_NOTHROW(from_text(replace(replace(kDruckerPrager, "young_modulus = 1.0e6", "young_modulus = 1e12"),
                                  "cohesion = 0.0", "cohesion = 1e12")));
}

TEST_CASE("overrides given with --set parse TOML values and bare words", "[parameters]") {
  toml::table root = toml::parse(kDruckerPrager);
  apply_override(root, "material.friction_angle=30");
  apply_override(root, "material.model=modified-cam-clay");
  apply_override(root, "scene.gravity=9.81");
  CHECK(root["material"]["friction_angle"].value<double>() == 30.0);
  CHECK(root["material"]["model"].value<std::string>() == "modified-cam-clay");
  CHECK(root["scene"]["gravity"].value<double>() == 9.81);
  CHECK_THROWS_AS(apply_override(root, "nodot=3"), ParameterError);
  CHECK_THROWS_AS(apply_override(root, "material.model"), ParameterError);
}

TEST_CASE("overrides reach named tables and the entries of arrays of tables by their number", "[parameters]") {
  toml::table root = toml::parse(R"(
[materials.clay]
cohesion = 100.0
[[regions]]
material = "clay"
[[regions]]
material = "sand"
)");
  apply_override(root, "materials.clay.cohesion=500");
  apply_override(root, "regions.2.material=clay");
  apply_override(root, "materials.sand.friction_angle=30");  // a table that does not exist yet
  CHECK(root["materials"]["clay"]["cohesion"].value<double>() == 500.0);
  CHECK(root["regions"][1]["material"].value<std::string>() == "clay");
  CHECK(root["regions"][0]["material"].value<std::string>() == "clay");
  CHECK(root["materials"]["sand"]["friction_angle"].value<double>() == 30.0);
  CHECK_THROWS_WITH(apply_override(root, "regions.3.material=clay"),
                    Contains("--set regions.3.material=clay: [[regions]] has 2 entries; name one by its number "
                             "from 1 (regions.1.material=...)"));
  CHECK_THROWS_WITH(apply_override(root, "regions.material=clay"),
                    Contains("[[regions]] is an array of tables; name an entry by its number from 1"));
  CHECK_THROWS_WITH(apply_override(root, "regions=3"), Contains("expected section.key=value"));
  CHECK_THROWS_WITH(apply_override(root, "materials.clay.cohesion.x=1"),
                    Contains("[materials.clay.cohesion] is not a table"));
  CHECK_THROWS_WITH(apply_override(root, "materials..cohesion=1"), Contains("an empty name in the key path"));
  CHECK_THROWS_WITH(apply_override(root, "material.=1"),
                    Contains("--set material.=1: an empty name in the key path"));
}

TEST_CASE("a bad value given with --set is blamed on the option, not on the file", "[parameters]") {
  const auto read = [](const std::string& assignment) {
    toml::table root = toml::parse(kDruckerPrager, std::string("case.toml"));
    apply_override(root, assignment);
    return read_material(TableReader(*root["material"].as_table(), "case.toml", "material"));
  };
  CHECK_THROWS_WITH(
      read("material.young_modulus=-5"),
      Contains("--set material.young_modulus=-5: [material] young_modulus = -5 is out of range") &&
          !Contains("case.toml"));
  CHECK_THROWS_WITH(
      read("material.model=cam-clay"),
      Contains("--set material.model=cam-clay: [material] model = \"cam-clay\" is not allowed"));
  CHECK_THROWS_WITH(
      read("material.frictoin_angle=30"),
      Contains("--set material.frictoin_angle=30: [material] frictoin_angle: is not a known key (did you "
               "mean \"friction_angle\"?)"));
  // A value the file holds is still blamed on the file when another key was overridden.
  CHECK_THROWS_WITH(read("material.poisson_ratio=0.7"), Contains("--set material.poisson_ratio=0.7"));
  toml::table root =
      toml::parse(replace(kDruckerPrager, "density = 2000.0", "density = 0.0"), std::string("case.toml"));
  apply_override(root, "material.friction_angle=30");
  CHECK_THROWS_WITH(read_material(TableReader(*root["material"].as_table(), "case.toml", "material")),
                    Contains("case.toml: [material] density = 0 is out of range"));
}

TEST_CASE("TOML syntax errors name the file and line", "[parameters]") {
  const std::string path = "soilsph-test-bad.toml";
  { std::ofstream(path) << "[material]\nmodel = \n"; }
  CHECK_THROWS_WITH(load_material(path), Contains("soilsph-test-bad.toml:2:"));
  std::remove(path.c_str());
}

TEST_CASE("string arrays are read with the allowed names in every message", "[parameters]") {
  const std::array<std::string_view, 3> allowed{"a", "b", "c"};
  const std::array<std::string_view, 2> fallback{"a", "c"};
  const auto read = [&](const std::string& text) {
    const toml::table root = toml::parse("[t]\n" + text);
    const TableReader reader(*root["t"].as_table(), "case.toml", "t");
    auto names = reader.choices_or("names", fallback, allowed);
    reader.reject_unknown_keys();
    return names;
  };
  using Names = std::vector<std::string>;
  CHECK(read("") == Names{"a", "c"});
  CHECK(read("names = [\"b\", \"a\"]") == Names{"b", "a"});
  CHECK(read("names = []").empty());
  const auto allowed_text = Contains(R"((allowed: "a", "b", "c"))");
  CHECK_THROWS_WITH(read("names = [\"a\", \"d\"]"),
                    Contains(R"(case.toml: [t] names: "d" is not allowed)") && allowed_text);
  CHECK_THROWS_WITH(read("names = \"a\""),
                    Contains("case.toml: [t] names: must be an array") && allowed_text);
  CHECK_THROWS_WITH(read("names = [\"a\", 2]"),
                    Contains("[t] names: must hold only strings") && allowed_text);
  CHECK_THROWS_WITH(read("names = [\"b\", \"b\"]"), Contains(R"([t] names: "b" is listed twice)"));
  CHECK_THROWS_AS(read("names = {a = 1}"), ParameterError);
}

TEST_CASE("an override (--set) may be a TOML array", "[parameters]") {
  toml::table root;
  apply_override(root, R"(output.fields=["p","q"])");
  const toml::array* fields = root["output"]["fields"].as_array();
  REQUIRE(fields);
  REQUIRE(fields->size() == 2);
  CHECK(fields->at(0).value<std::string>() == "p");
  CHECK(fields->at(1).value<std::string>() == "q");
  // What a shell leaves of an unquoted ["p","q"] is not taken for the string "[p,q]".
  CHECK_THROWS_WITH(apply_override(root, "output.fields=[p,q]"),
                    Contains("--set output.fields=[p,q]: not a TOML value") &&
                        Contains(R"(--set 'output.fields=["a","b"]')"));
}

// What a result records of its material reads back to the same model: every key present (each
// optional one set off its default, so a missing key would read back as the default) and exact.
TEST_CASE("a described material reads back to the same parameters", "[parameters]") {
  const auto read_back = [](const Material& material) {
    std::string table = "[material]\n" + describe_material(material);
    for (std::size_t at; (at = table.find("; ")) != std::string::npos;) table.replace(at, 2, "\n");
    return from_text(table);
  };
  const Material dp = from_text(replace(replace(kDruckerPrager, "cohesion = 0.0", "cohesion = 1234.5678"),
                                        "dilatancy_angle = 0.0", "dilatancy_angle = 0.1") +
                                "integrator = \"substep\"\nsubstep_tolerance = 3e-7\n"
                                "plastic_potential = \"paper-eq20\"\n");
  const auto& a = std::get<DruckerPrager>(dp).params();
  const Material dp_read = read_back(dp);  // kept: params() refers into it
  const auto& b = std::get<DruckerPrager>(dp_read).params();
  CHECK(std::tie(a.density, a.young_modulus, a.poisson_ratio, a.friction_angle, a.cohesion, a.dilatancy_angle,
                 a.plastic_potential, a.integrator, a.substep_tolerance) ==
        std::tie(b.density, b.young_modulus, b.poisson_ratio, b.friction_angle, b.cohesion, b.dilatancy_angle,
                 b.plastic_potential, b.integrator, b.substep_tolerance));
  CHECK(a.plastic_potential == PlasticPotential::PaperEq20);
  CHECK(std::get<DruckerPrager>(from_text(kDruckerPrager)).params().plastic_potential ==
        PlasticPotential::Matched);
  const Material mcc = from_text(kCamClay + "elastic_pressure_floor = 1.0e-1\nintegrator = \"explicit\"\n" +
                                 "substep_tolerance = 1e-9\nimplicit_alpha = 0.75\n");
  const auto& c = std::get<ModifiedCamClay>(mcc).params();
  const Material mcc_read = read_back(mcc);
  const auto& d = std::get<ModifiedCamClay>(mcc_read).params();
  CHECK(std::tie(c.density, c.poisson_ratio, c.friction_angle, c.compression_index, c.swelling_index,
                 c.initial_void_ratio, c.elasticity, c.elastic_pressure_floor, c.integrator,
                 c.substep_tolerance, c.implicit_alpha) ==
        std::tie(d.density, d.poisson_ratio, d.friction_angle, d.compression_index, d.swelling_index,
                 d.initial_void_ratio, d.elasticity, d.elastic_pressure_floor, d.integrator,
                 d.substep_tolerance, d.implicit_alpha));
  const Material elastic = from_text(
      "[material]\nmodel = \"linear-elastic\"\ndensity = 1.5e3\n"
      "young_modulus = 2.5\npoisson_ratio = -0.2\n");
  CHECK(describe_material(read_back(elastic)) ==
        "model = \"linear-elastic\"; density = 1500; young_modulus = 2.5; poisson_ratio = -0.2");
}

// A model built in code goes through the same ranges and defaults as one read from TOML.
TEST_CASE("a model built in code from bad parameters throws, naming the key", "[parameters]") {
  DruckerPrager::Params dp;
  dp.density = 2000.0, dp.young_modulus = 1.0e6, dp.poisson_ratio = 0.3, dp.friction_angle = 30.0;
  CHECK_NOTHROW(DruckerPrager(dp));
  dp.dilatancy_angle = 31.0;  // ψ > φ
  CHECK_THROWS_WITH(DruckerPrager(dp), Contains("drucker-prager parameters: dilatancy_angle = 31") &&
                                           Contains("0 <= value <= 30 degrees"));
  dp.dilatancy_angle = 0.0, dp.poisson_ratio = 0.5;
  CHECK_THROWS_AS(DruckerPrager(dp), ParameterError);
  CHECK_THROWS_WITH(DruckerPrager(dp), Contains("poisson_ratio = 0.5"));

  ModifiedCamClay::Params mcc;
  mcc.density = 2000.0, mcc.poisson_ratio = 0.3, mcc.friction_angle = 35.0;
  mcc.compression_index = 0.085, mcc.swelling_index = 0.019, mcc.initial_void_ratio = 0.68;
  CHECK_NOTHROW(ModifiedCamClay(mcc));
  mcc.swelling_index = 0.085;  // κ = λ
  CHECK_THROWS_WITH(ModifiedCamClay(mcc), Contains("modified-cam-clay parameters: swelling_index = 0.085") &&
                                              Contains("0 < value < 0.085"));
  mcc.swelling_index = 0.019, mcc.elasticity = Elasticity::Kind::Constant;  // E is then required
  CHECK_THROWS_WITH(ModifiedCamClay(mcc), Contains("young_modulus = 0"));
  CHECK_THROWS_WITH(LinearElastic(LinearElastic::Params{}), Contains("linear-elastic parameters: density = 0"));
}

TEST_CASE("a model built in code checks its derived constants, as a file's material", "[parameters]") {
  DruckerPrager::Params dp;
  dp.density = 2000.0, dp.young_modulus = 1e6, dp.poisson_ratio = 0.3;
  dp.friction_angle = 1e-300, dp.cohesion = 1e7;  // the apex 3c/tan φ overflows
  CHECK_THROWS_WITH(DruckerPrager(dp), Contains("cohesion = 1e7 gives the apex's I1"));

  MohrCoulomb::Params mc;
  mc.density = 2000.0, mc.young_modulus = 1e6, mc.poisson_ratio = 0.3, mc.friction_angle = 1e-300;
  mc.cohesion = 1e7;  // c cot φ overflows
  CHECK_THROWS_WITH(MohrCoulomb(mc), Contains("mohr-coulomb parameters: cohesion = 1e7 gives the apex"));

  ModifiedCamClay::Params mcc;
  mcc.density = 2000.0, mcc.poisson_ratio = 0.3, mcc.friction_angle = 35.0;
  mcc.compression_index = 0.085, mcc.swelling_index = 0.019, mcc.initial_void_ratio = 1e308;
  CHECK_THROWS_WITH(ModifiedCamClay(mcc), Contains("initial_void_ratio = 1e308 gives (1+e0)/(lambda-kappa)"));
  CHECK_THROWS_AS(ModifiedCamClay(mcc), ParameterError);
  CHECK_THROWS_WITH(LinearElastic({2000.0, 5e-324, 0.3}), Contains("linear-elastic parameters: young_modulus"));
}

TEST_CASE("a model built in code has the defaults of an input file", "[parameters]") {
  const DruckerPrager::Params dp_code;
  const Material dp_read = from_text(
      "[material]\nmodel = \"drucker-prager\"\ndensity = 2000.0\nyoung_modulus = 1.0e6\n"
      "poisson_ratio = 0.3\nfriction_angle = 35.0\n");  // kept: params() refers into it
  const auto& dp_toml = std::get<DruckerPrager>(dp_read).params();
  CHECK(dp_code.integrator == dp_toml.integrator);
  CHECK(dp_code.integrator == Integrator::Implicit);
  CHECK(std::tie(dp_code.cohesion, dp_code.dilatancy_angle, dp_code.plastic_potential, dp_code.substep_tolerance) ==
        std::tie(dp_toml.cohesion, dp_toml.dilatancy_angle, dp_toml.plastic_potential, dp_toml.substep_tolerance));
  const ModifiedCamClay::Params mcc_code;
  const Material mcc_read = from_text(kCamClay);
  const auto& mcc_toml = std::get<ModifiedCamClay>(mcc_read).params();
  CHECK(std::tie(mcc_code.integrator, mcc_code.elasticity, mcc_code.elastic_pressure_floor,
                 mcc_code.substep_tolerance, mcc_code.implicit_alpha, mcc_code.implicit_tolerance) ==
        std::tie(mcc_toml.integrator, mcc_toml.elasticity, mcc_toml.elastic_pressure_floor,
                 mcc_toml.substep_tolerance, mcc_toml.implicit_alpha, mcc_toml.implicit_tolerance));
}

TEST_CASE("mohr-coulomb reads the D-P keys and an optional tension cut-off", "[parameters][mohr-coulomb]") {
  const std::string mc = replace(kDruckerPrager, "model = \"drucker-prager\"", "model = \"mohr-coulomb\"");
  const MohrCoulomb plain = std::get<MohrCoulomb>(from_text(mc));
  CHECK(plain.params().tension_cutoff == MohrCoulomb::Params::kNoTensionCutoff);
  CHECK(plain.integrator() == Integrator::Implicit);
  CHECK(std::get<MohrCoulomb>(from_text(mc + "tension_cutoff = 1000.0\n")).tension_cutoff() == 1000.0);
  CHECK_THROWS_WITH(from_text(mc + "tension_cutoff = -1.0\n"), Contains("[material] tension_cutoff = -1"));
  CHECK_THROWS_WITH(from_text(replace(mc, "dilatancy_angle = 0.0", "dilatancy_angle = 40.0")),
                    Contains("[material] dilatancy_angle = 40"));
  // What a result records of it reads back (the cut-off only when given).
  CHECK(describe_material(from_text(mc)).find("tension_cutoff") == std::string::npos);
  CHECK(describe_material(from_text(mc + "tension_cutoff = 1000.0\n")).find("tension_cutoff = 1000") !=
        std::string::npos);
}

// The description of a result is written from the same fields() list the reader reads: a material
// that sets every key of its model has each of them in its description, with the value it set.
TEST_CASE("a material that sets every key of its model is described with every key", "[parameters]") {
  const std::string dp =
      "[material]\nmodel = \"drucker-prager\"\ndensity = 2100\nyoung_modulus = 2000000\npoisson_ratio = 0.25\n"
      "friction_angle = 32\ncohesion = 1500\ndilatancy_angle = 4\ndilatancy_cutoff = 0.05\n"
      "viscoplastic_relaxation_time = 0.01\nplastic_potential = \"paper-eq20\"\nintegrator = \"substep\"\n"
      "substep_tolerance = 0.0000001\n";
  const std::string mc =
      "[material]\nmodel = \"mohr-coulomb\"\ndensity = 2100\nyoung_modulus = 2000000\npoisson_ratio = 0.25\n"
      "friction_angle = 32\ncohesion = 1500\ndilatancy_angle = 4\ndilatancy_cutoff = 0.05\n"
      "viscoplastic_relaxation_time = 0.01\nintegrator = \"explicit\"\nsubstep_tolerance = 0.0000001\n"
      "tension_cutoff = 500\n";
  const std::string mcc_common =
      "[material]\nmodel = \"modified-cam-clay\"\ndensity = 2100\npoisson_ratio = 0.25\nfriction_angle = 32\n"
      "compression_index = 0.1\nswelling_index = 0.02\ninitial_void_ratio = 0.7\nintegrator = \"explicit\"\n"
      "substep_tolerance = 0.0000001\nimplicit_alpha = 0.75\nimplicit_tolerance = 0.00001\n"
      "minimum_preconsolidation = 10\nhardening_volume = \"current\"\nviscoplastic_relaxation_time = 0.01\n";
  const std::string mcc_constant = mcc_common + "elasticity = \"constant\"\nyoung_modulus = 2000000\n";
  const std::string mcc_pressure = mcc_common + "elasticity = \"pressure-dependent\"\nelastic_pressure_floor = 500\n";
  const std::string elastic =
      "[material]\nmodel = \"linear-elastic\"\ndensity = 2100\nyoung_modulus = 2000000\npoisson_ratio = 0.25\n";
  // Each file's `key = value` lines, as the description should hold them.
  const auto assignments = [](const std::string& text) {
    std::vector<std::string> lines;
    for (std::size_t from = text.find('\n') + 1, to; (to = text.find('\n', from)) != std::string::npos; from = to + 1)
      lines.push_back(text.substr(from, to - from));
    return lines;
  };
  const auto check_every_key = [&](const std::vector<std::string>& files, std::vector<std::string_view> keys) {
    for (const std::string& file : files) {
      const std::string description = "; " + describe_material(from_text(file)) + ";";
      INFO(description);
      for (const std::string& line : assignments(file)) CHECK_THAT(description, Contains("; " + line + ";"));
      for (const std::string& line : assignments(file)) std::erase(keys, line.substr(0, line.find(" = ")));
    }
    CHECK(keys.empty());  // every key the model reads was set in one of the files
  };
  check_every_key({dp}, field_keys<DruckerPrager::Params>());
  check_every_key({mc}, field_keys<MohrCoulomb::Params>());
  check_every_key({mcc_constant, mcc_pressure}, field_keys<ModifiedCamClay::Params>());
  check_every_key({elastic}, field_keys<LinearElastic::Params>());
  // And every key the reader accepts belongs to some model.
  for (const std::string_view key :
       {"dilatancy_cutoff", "hardening_volume", "tension_cutoff", "library", "thread_safe", "model"}) {
    const auto keys = material_keys();
    CHECK(std::find(keys.begin(), keys.end(), key) != keys.end());
  }
}

namespace {
enum class Shade { Light, Dark };
constexpr auto kShadeTable = enum_table<Shade>({{Shade::Light, "light"}, {Shade::Dark, "dark"}});

/// A table of every kind of field, each with the house messages.
struct Gadget {
  std::string label = "g";
  int count = 2;
  std::vector<double> weights;
  bool enabled = false;
  Shade shade = Shade::Light;

  template <class Io>
  void fields(const Io& io) {
    io.text_or("label", label, Length::at_most(4));
    io.integer_or("count", count, 0, 5);
    io.numbers_or("weights", weights, Range::non_negative(),
                  Count::none_or_exactly(static_cast<std::size_t>(count), "count"));
    io.boolean_or("enabled", enabled);
    io.choice_or("shade", shade, kShadeTable);
  }
};

Gadget gadget_from(const std::string& lines) {
  const toml::table root = toml::parse("[gadget]\n" + lines);
  const TableReader table(*root["gadget"].as_table(), "gadget.toml", "gadget");
  const Gadget gadget = read_fields<Gadget>(table);
  table.reject_unknown_keys();
  return gadget;
}
}  // namespace

TEST_CASE("string, integer, array and bool fields are read, checked, described and listed from one list",
          "[parameters]") {
  const Gadget g =
      gadget_from("label = \"ab\"\ncount = 3\nweights = [1, 0.5, 2]\nenabled = true\nshade = \"dark\"\n");
  CHECK(g.label == "ab");
  CHECK(g.count == 3);
  CHECK(g.weights == std::vector<double>{1.0, 0.5, 2.0});
  CHECK(g.enabled);
  CHECK(g.shade == Shade::Dark);
  CHECK(described_fields(g) == KeyValues{{"label", "\"ab\""},
                                         {"count", "3"},
                                         {"weights", "[1, 0.5, 2]"},
                                         {"enabled", "true"},
                                         {"shade", "\"dark\""}});
  CHECK(field_keys<Gadget>() ==
        std::vector<std::string_view>{"label", "count", "weights", "enabled", "shade"});
  // Absent keys keep the struct's initial values; no weights at all is allowed whatever the count.
  const Gadget defaults = gadget_from("");
  CHECK(defaults.label == "g");
  CHECK(defaults.count == 2);
  CHECK(defaults.weights.empty());
  CHECK(!defaults.enabled);
  CHECK_NOTHROW(validated(defaults, "gadget"));
}

TEST_CASE("bad string, integer, array and bool fields name the file, table, key and what is allowed",
          "[parameters]") {
  struct Case {
    std::string lines, message;
  };
  const std::vector<Case> cases = {
      {"label = \"toolong\"\n",
       "gadget.toml: [gadget] label = \"toolong\" has 7 characters (allowed: at most 4 characters)"},
      {"label = 4\n", "gadget.toml: [gadget] label: must be a string"},
      {"shade = \"grey\"\n",
       "gadget.toml: [gadget] shade = \"grey\" is not allowed (allowed: \"light\", \"dark\")"},
      {"count = 3\nweights = [1, 2]\n",
       "gadget.toml: [gadget] weights: has 2 values (allowed: 0 or 3 values, as count = 3)"},
      {"weights = [1, -2]\n",
       "gadget.toml: [gadget] weights: element 2 = -2 is out of range (allowed: 0 <= value)"},
      {"weights = 1\n", "gadget.toml: [gadget] weights: must be an array of numbers (allowed: 0 <= value)"},
      {"enabled = 1\n", "gadget.toml: [gadget] enabled: must be true or false"},
      {"enabled = \"yes\"\n", "gadget.toml: [gadget] enabled: must be true or false"},
      {"count = 6\n", "gadget.toml: [gadget] count = 6 is out of range (allowed: 0 <= value <= 5)"},
      {"count = 2.5\n", "gadget.toml: [gadget] count: must be an integer"},
  };
  for (const Case& c : cases) {
    INFO(c.lines);
    CHECK_THROWS_WITH(gadget_from(c.lines), c.message);
    CHECK_THROWS_AS(gadget_from(c.lines), ParameterError);
  }
  // A struct built in code is checked against the same list.
  Gadget long_label;
  long_label.label = "toolong";
  CHECK_THROWS_WITH(
      validated(long_label, "gadget"),
      "gadget parameters: label = \"toolong\" has 7 characters (allowed: at most 4 characters)");
  Gadget short_weights;
  short_weights.weights = {1.0};
  CHECK_THROWS_WITH(validated(short_weights, "gadget"),
                    "gadget parameters: weights = [1] has 1 values (allowed: 0 or 2 values, as count = 2)");
  Gadget many;
  many.count = -1;
  CHECK_THROWS_WITH(validated(many, "gadget"),
                    "gadget parameters: count = -1 is out of range (allowed: 0 <= value <= 5)");
}

TEST_CASE("an unknown key is refused with the nearest known key when one is close", "[parameters]") {
  const std::vector<std::string_view> known = {"friction_angle", "cohesion", "column_height", "column_width"};
  CHECK(nearest_key("frictoin_angle", known) == "friction_angle");  // two letters swapped: one edit
  CHECK(nearest_key("frictionangle", known) == "friction_angle");   // one deleted
  CHECK(nearest_key("column_heigt", known) == "column_height");
  CHECK(nearest_key("column_widht", known) == "column_width");
  CHECK(nearest_key("cohesoin_x", known) == std::nullopt);  // three edits
  CHECK(nearest_key("xyz", known) == std::nullopt);
  CHECK(nearest_key("cohesin", known) == "cohesion");  // 7 letters: up to 2 edits
  CHECK(nearest_key("cohe", known) == std::nullopt);   // 4 letters: 1 edit at most, 4 needed
  CHECK_THROWS_WITH(gadget_from("lable = \"x\"\n"),
                    "gadget.toml: [gadget] lable: is not a known key (did you mean \"label\"?)");
  CHECK_THROWS_WITH(gadget_from("colour = \"x\"\n"), "gadget.toml: [gadget] colour: is not a known key");
  CHECK_THROWS_WITH(
      from_text(kDruckerPrager + "frictionangle = 30.0\n"),
      "case.toml: [material] frictionangle: is not a known key (did you mean \"friction_angle\"?)");
}
