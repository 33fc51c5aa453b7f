// Verification cases as data: the shipped files parse, and every invalid entry is reported with the
// file, the case and the key.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "constitutive/parameters.h"
#include "verification/report/verification_case.h"
#include "../common/temp_dir.h"

using namespace soilsph;
using namespace soilsph::verification;
namespace fs = std::filesystem;

namespace {
const fs::path kCases = fs::path(SOILSPH_SOURCE_DIR) / "verification" / "cases";

/// Writes a one-case file next to the shipped cases' materials (so relative paths resolve) and
/// returns the ParameterError message of reading it ("" if it reads).
std::string error_of(const std::string& body) {
  static const soilsph::testing::TempDir dir("soilsph-cases");  // one per test process
  const fs::path file = dir / "soilsph-case-under-test.toml";
  std::ofstream(file) << "[[case]]\nname = \"x\"\nmaterial = \""
                      << (kCases / "materials" / "mcc-pressure-dependent.toml").string() << "\"\n"
                      << body;
  try {
    read_case_file(file);
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the shipped verification cases parse and all run the CVODE reference", "[cases]") {
  const auto cases = read_cases(kCases);
  REQUIRE(cases.size() >= 15);
  for (const VerificationCase& c : cases) {
    INFO(c.name);
    CHECK(std::any_of(c.tolerances.begin(), c.tolerances.end(),
                      [](const auto& t) { return t.first == "cvode"; }));
  }
}

TEST_CASE("an invalid case names the file, the case and the key", "[cases]") {
  const std::string good = "path = \"oedometer\"\nstrain_targets = [0.1]\ntolerance = { cvode = 1e-5 }\n";
  CHECK(error_of(good).empty());
  const std::string unknown = error_of(good + "colour = 3\n");
  CHECK_THAT(unknown, Catch::Contains("soilsph-case-under-test.toml") && Catch::Contains("case[0]") &&
                          Catch::Contains("colour"));
  CHECK_THAT(error_of(good + "ocr = 0.5\n"), Catch::Contains("ocr"));
  // The ranges of `soilsph point` (point_limits), so a case never fails at run time on its inputs.
  CHECK_THAT(error_of(good + "p_initial = 0.5\n"),
             Catch::Contains("p_initial = 0.5 is out of range (allowed: 1 <= value <= 1e12 Pa)"));
  CHECK_THAT(error_of(good + "closed_form = \"mcc-triaxial-drained\"\n"), Catch::Contains("closed_form"));
  CHECK_THAT(error_of("path = \"oedometer\"\nstrain_targets = [0.1]\ntolerance = { rk4 = 1e-3 }\n"),
             Catch::Contains("rk4") && Catch::Contains("cvode"));
  CHECK_THAT(error_of("path = \"shear\"\nstrain_targets = [0.1]\ntolerance = { cvode = 1e-5 }\n"),
             Catch::Contains("path"));
  CHECK_THAT(error_of("path = \"oedometer\"\nstrain_targets = []\ntolerance = { cvode = 1e-5 }\n"),
             Catch::Contains("strain_targets"));
  CHECK_THAT(error_of("path = \"oedometer\"\nstrain_targets = [0.1]\n"), Catch::Contains("tolerance"));
}
