// Input validation: every bad value names the file, the key and the allowed range.
#include <catch2/catch.hpp>

#include <array>
#include <fstream>

#include "helpers.h"

using namespace soilsph;
using Catch::Matchers::Contains;

namespace {
Material from_text(const std::string& text) {
  const toml::table root = toml::parse(text);
  return read_material(TableReader(*root["material"].as_table(), "case.toml", "material"));
}
const std::string kDruckerPrager = R"(
[material]
model = "drucker-prager"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 35.0
cohesion = 0.0
dilatancy_angle = 0.0
)";
const std::string kCamClay = R"(
[material]
model = "modified-cam-clay"
density = 2000.0
poisson_ratio = 0.3
friction_angle = 35.0
compression_index = 0.085
swelling_index = 0.019
initial_void_ratio = 0.68
)";
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
}

TEST_CASE("invalid parameters are rejected with file, key and range", "[parameters]") {
  CHECK_NOTHROW(from_text(kDruckerPrager));
  CHECK_NOTHROW(from_text(kCamClay));
  struct Case {
    std::string text, message;
  };
  const std::vector<Case> cases = {
      {replace(kDruckerPrager, "young_modulus = 1.0e6", "young_modulus = -5.0"),
       "case.toml: [material] young_modulus = -5 is out of range (allowed: 0 < value Pa)"},
      {replace(kDruckerPrager, "poisson_ratio = 0.3", "poisson_ratio = 0.5"),
       "[material] poisson_ratio = 0.5 is out of range (allowed: -1 < value < 0.5)"},
      {replace(kDruckerPrager, "friction_angle = 35.0", "friction_angle = 90"),
       "[material] friction_angle = 90 is out of range (allowed: 0 < value < 90 degrees)"},
      {replace(kDruckerPrager, "cohesion = 0.0", "cohesion = -1.0"),
       "[material] cohesion = -1 is out of range (allowed: 0 <= value Pa)"},
      {replace(kDruckerPrager, "dilatancy_angle = 0.0", "dilatancy_angle = 40.0"),
       "[material] dilatancy_angle = 40 is out of range (allowed: 0 <= value <= 35 degrees)"},
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
       "\"modified-cam-clay\")"},
      {kDruckerPrager + "integrator = \"rk4\"\n", "[material] integrator = \"rk4\" is not allowed"},
      {kCamClay + "elasticity = \"nonlinear\"\n", "[material] elasticity = \"nonlinear\" is not allowed"},
      {kCamClay + "elasticity = \"constant\"\n", "[material] young_modulus: is missing"},
      {kDruckerPrager + "frictoin_angle = 30.0\n", "case.toml: [material] frictoin_angle: is not a known key"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK_THROWS_WITH(from_text(c.text), Contains(c.message));
    CHECK_THROWS_AS(from_text(c.text), ParameterError);
  }
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
