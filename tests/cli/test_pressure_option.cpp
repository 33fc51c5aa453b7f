// Pressures on the command line with a unit (apps/soilsph/pressure_option.h): each unit's factor to
// Pa, the correctly rounded value, the refusals; and `soilsph point --p-initial` end to end.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../common/temp_dir.h"
#include "apps/soilsph/pressure_option.h"

namespace {
namespace fs = std::filesystem;
using soilsph::cli::parse_pressure;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The file without its `# command:` line, which records the options as typed.
std::string without_command_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, kept;
  while (std::getline(in, line))
    if (!line.starts_with("# command:")) kept += line + '\n';
  return kept;
}

using soilsph::testing::TempDir;

/// Runs `soilsph point` on the shipped MCC material with `p_initial`; returns the exit status.
int point_with(const std::string& p_initial, const fs::path& out, const fs::path& log) {
  const std::string command =
      std::string(SOILSPH_EXECUTABLE) + " point " + SOILSPH_SOURCE_DIR +
      "/data/materials/mcc-table1.toml --test isotropic --strain-max 0.01 --increments 3 "
      "--p-initial " +
      p_initial + " --out " + out.string() + " 2> " + log.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST_CASE("a pressure reads in Pa from each unit", "[cli][pressure]") {
  CHECK(parse_pressure("100000") == 1e5);
  CHECK(parse_pressure("100000Pa") == 1e5);
  CHECK(parse_pressure("100kPa") == 1e5);
  CHECK(parse_pressure("0.1MPa") == 1e5);  // 0.1 * 1e6 in doubles is 100000.00000000001
  CHECK(parse_pressure("1e-4GPa") == 1e5);
  CHECK(parse_pressure("2.5e2kPa") == 2.5e5);
  CHECK(parse_pressure("1.5GPa") == 1.5e9);
  CHECK(parse_pressure("0.3kPa") == 300.0);
  CHECK(parse_pressure("1e5") == 1e5);
  CHECK(parse_pressure("-20kPa") == -2e4);  // a sign is the number's; the option's range refuses it
}

TEST_CASE("a pressure with an unknown unit or no number is refused", "[cli][pressure]") {
  for (const char* text : {"100kpa", "100KPa", "100 kPa", "100mPa", "100bar", "kPa", "", "1e", "1ekPa",
                           "e5kPa", "100kPa ", "1.2.3kPa", "0x10kPa", "1e999kPa"})
    CHECK_FALSE(parse_pressure(text).has_value());
}

TEST_CASE("soilsph point --p-initial takes a unit; the CSV stays in Pa", "[cli][pressure]") {
  TempDir dir("soilsph-pressure");
  REQUIRE(point_with("100000", dir.path() / "pa.csv", dir.path() / "log") == 0);
  const std::string in_pa = without_command_line(read(dir.path() / "pa.csv"));
  for (const char* same : {"100kPa", "0.1MPa", "100000Pa"}) {
    REQUIRE(point_with(same, dir.path() / "unit.csv", dir.path() / "log") == 0);
    CHECK(without_command_line(read(dir.path() / "unit.csv")) == in_pa);
  }
  // A bad unit: exit 2, the option named, the units listed; nothing written.
  REQUIRE(point_with("100kpa", dir.path() / "bad.csv", dir.path() / "log") == 2);
  const std::string message = read(dir.path() / "log");
  CHECK(message.find("--p-initial") != std::string::npos);
  CHECK(message.find("100kpa is not a pressure") != std::string::npos);
  CHECK(message.find("Pa, kPa, MPa, GPa") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path() / "bad.csv"));
  // Out of range in any unit names the range in Pa.
  REQUIRE(point_with("0.5Pa", dir.path() / "low.csv", dir.path() / "log") == 2);
  CHECK(read(dir.path() / "log").find("0.5Pa is out of range") != std::string::npos);
}
