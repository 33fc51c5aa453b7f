// summary.json: the contract's field names, JSON escaping and numbers that read back exactly.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "sph/output/summary.h"
#include "../common/temp_dir.h"

using namespace soilsph::sph;

namespace {

Summary example() {
  Summary s;
  s.model = "drucker-prager";
  s.integrator = "explicit";
  s.particles = 2501;
  s.boundary_particles = 1132;
  s.steps = 123456;
  s.threads = 2;
  s.end_time = 0.2;
  s.wall_seconds = 12.5;
  s.particle_steps_per_second = 2501.0 * 123456 / 12.5;
  s.runout_m = 0.1 + 0.2;  // 0.30000000000000004: needs 17 significant digits
  s.height_m = 0.047;
  s.repose_angle_deg = 1.0 / 3.0;
  s.max_speed_end = 1e-300;
  s.kinetic_energy_end = 6.02e23;
  s.particle_spacing = 1e-3;
  s.smoothing_ratio = 1.2;
  s.time_step = 2.5e-6;
  return s;
}

/// The raw value text of "key": value in flat JSON.
std::string value_of(const std::string& json, const std::string& key) {
  const std::regex field("\"" + key + "\": ([^,\\n]+)");
  std::smatch match;
  if (!std::regex_search(json, match, field)) return "<missing>";
  return match[1];
}

}  // namespace

TEST_CASE("summary.json holds every contract field and numbers read back exactly", "[summary]") {
  const Summary s = example();
  const std::string json = summary_json(s);
  CHECK(value_of(json, "model") == "\"drucker-prager\"");
  CHECK(value_of(json, "integrator") == "\"explicit\"");
  CHECK(value_of(json, "particles") == "2501");
  CHECK(value_of(json, "boundary_particles") == "1132");
  CHECK(value_of(json, "steps") == "123456");
  CHECK(value_of(json, "threads") == "2");
  const std::pair<const char*, double> numbers[] = {
      {"end_time", s.end_time},
      {"wall_seconds", s.wall_seconds},
      {"particle_steps_per_second", s.particle_steps_per_second},
      {"runout_m", s.runout_m},
      {"height_m", s.height_m},
      {"repose_angle_deg", s.repose_angle_deg},
      {"max_speed_end", s.max_speed_end},
      {"kinetic_energy_end", s.kinetic_energy_end},
      {"particle_spacing", s.particle_spacing},
      {"smoothing_ratio", s.smoothing_ratio},
      {"time_step", s.time_step}};
  for (const auto& [key, value] : numbers) {
    INFO(key << " = " << value_of(json, key));
    CHECK(std::strtod(value_of(json, key).c_str(), nullptr) == value);
  }
  CHECK(json.front() == '{');
  CHECK(json.find('}') == json.size() - 2);
}

TEST_CASE("strings are JSON-escaped and non-finite numbers become null", "[summary]") {
  Summary s = example();
  s.model = "a \"quoted\" back\\slash\nnew line\ttab\x01";
  s.runout_m = std::nan("");
  s.height_m = INFINITY;
  const std::string json = summary_json(s);
  CHECK(value_of(json, "model") == R"("a \"quoted\" back\\slash\nnew line\ttab\u0001")");
  CHECK(value_of(json, "runout_m") == "null");
  CHECK(value_of(json, "height_m") == "null");
}

TEST_CASE("write_summary_json writes the text to the file, creating its folder", "[summary]") {
  const soilsph::testing::TempDir scratch("soilsph-summary");
  const auto dir = scratch.path();
  const auto file = dir / "run" / "summary.json";
  write_summary_json(file, example());
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == summary_json(example()));
  CHECK_FALSE(std::filesystem::exists(dir / "run" / "summary.json.tmp"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("summary.json records completion, provenance and the inputs as a nested object", "[summary]") {
  Summary s;
  s.stop_reason = "blow-up: \"x\"\nsecond line";
  s.version = "0.1.0 (abc)";
  s.command_line = "soilsph collapse 'a b.toml'";
  s.inputs_json = "{\n    \"scene\" : {\n        \"gravity\" : 9.81\n    }\n}";
  const std::string json = summary_json(s);
  CHECK(json.find("\"complete\": false") != std::string::npos);
  CHECK(json.find("\"stop_reason\": \"blow-up: \\\"x\\\"\\nsecond line\"") != std::string::npos);
  CHECK(json.find("\"resumed_from\": null") != std::string::npos);
  CHECK(json.find("\"command_line\": \"soilsph collapse 'a b.toml'\"") != std::string::npos);
  CHECK(json.find("\"inputs\": {\n      \"scene\" : {\n          \"gravity\" : 9.81\n      }\n  }\n}") !=
        std::string::npos);
  s.complete = true;
  s.resumed_from = 0.25;
  CHECK(summary_json(s).find("\"complete\": true") != std::string::npos);
  CHECK(summary_json(s).find("\"resumed_from\": 0.25") != std::string::npos);
}

TEST_CASE("summary.json names each wall's kind, a symmetry line as \"symmetry\"", "[summary]") {
  Summary s = example();
  Wall axis{.points = {{0.0, 0.04}, {0.0, 0.0}}, .kind = WallKind::FreeSlip, .label = "axis", .symmetry_plane = true};
  Wall side{.points = {{0.02, 0.0}, {0.02, 0.04}}, .kind = WallKind::FreeSlip, .label = "side"};
  Wall floor{.points = {{0.0, 0.0}, {0.02, 0.0}}, .kind = WallKind::NoSlip, .label = "floor"};
  s.boundaries = {axis, side, floor};
  const std::string json = summary_json(s);
  CHECK(json.find(R"({"name": "axis", "kind": "symmetry", )") != std::string::npos);
  CHECK(json.find(R"({"name": "side", "kind": "free-slip", )") != std::string::npos);
  CHECK(json.find(R"({"name": "floor", "kind": "no-slip", )") != std::string::npos);
}
