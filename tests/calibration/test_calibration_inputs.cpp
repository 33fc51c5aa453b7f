// Every bad input of a calibration is refused with one line that names the file and the row or the
// key at fault: never a crash, a silent default or a fit on wrong data.
#include <catch2/catch.hpp>
#include <regex>

#include "tests/calibration/calibration_fixtures.h"
#include "verification/calibration/calibrate.h"

using namespace soilsph;
using namespace soilsph::calibration;
using namespace soilsph::calibration::testing;

namespace {

const std::string kMaterial =
    "model = \"drucker-prager\"\ndensity = 1900\npoisson_ratio = 0.3\nfriction_angle = 30\n"
    "cohesion = 5000\ndilatancy_angle = 5\nyoung_modulus = 20e6\nintegrator = \"implicit\"\n";
const std::string kProgramme =
    "[initial]\np = 100000\n[[leg]]\nincrements = 20\nstrain = { xx = 0.02 }\nstress = { yy = \"hold\", zz = "
    "\"hold\" }\n";
const std::string kData =
    "eps_a,q,eps_v\n0.005,90e3,0.001\n0.01,150e3,0.0015\n0.015,180e3,0.0015\n0.02,190e3,0.001\n";

/// A calibration file in its own folder with one experiment; each piece replaceable.
struct Setup {
  TempDir dir;
  std::string material = kMaterial;
  std::string parameters = "parameters = { friction_angle = [20, 40], young_modulus = [1e6, 1e8] }";
  std::string experiment =
      "programme = \"cd.toml\"\ndata = \"cd.csv\"\nagainst = \"eps_a\"\nmatch = [\"q\", \"eps_v\"]\n";
  std::string programme = kProgramme;
  std::string data = kData;

  std::string write() const {
    dir.file("cd.toml", programme);
    dir.file("cd.csv", data);
    return dir.file("cal.toml",
                    "[material]\n" + material + "\n[fit]\n" + parameters + "\n[[experiment]]\n" + experiment);
  }
};

/// The message of the ParameterError that reading and calibrating `setup` throws.
std::string refusal(const Setup& setup) {
  const std::string path = setup.write();
  try {
    calibrate(read_calibration_file(path));
  } catch (const ParameterError& e) {
    const std::string message = e.what();
    CHECK(message.find('\n') == std::string::npos);  // one line
    return message;
  }
  FAIL("no ParameterError");
  return "";
}

}  // namespace

TEST_CASE("The valid setup of these tests calibrates", "[calibration]") {
  Setup setup;
  const Calibration result = calibrate(read_calibration_file(setup.write()));
  CHECK(result.statistics.parameters.size() == 2);
}

TEST_CASE("A measured CSV with a missing, NaN or non-monotonic driven value names the file and line",
          "[calibration]") {
  Setup setup;
  SECTION("missing") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0.001\n,150e3,0.0015\n0.015,180e3,0.0015\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv:3: eps_a is missing"));
  }
  SECTION("NaN in a matched column") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0.001\n0.01,nan,0.0015\n0.015,180e3,0.0015\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv:3: q = nan is not a finite number"));
  }
  SECTION("not a number") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0.001\n0.01,15O,0.0015\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv:3: q = 15O is not a number"));
  }
  SECTION("non-monotonic") {
    setup.data = "# a comment\neps_a,q,eps_v\n0.005,90e3,0.001\n0.01,150e3,0.0015\n0.008,180e3,0.0015\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv:5: eps_a = 0.008 after 0.01 at line 4") &&
                                   Catch::Contains("strictly increasing"));
  }
  SECTION("a row short of fields") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0.001\n0.01,150e3\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv:3: 2 fields where the header row has 3"));
  }
  SECTION("a column the file lacks") {
    setup.data = "eps_a,q\n0.005,90e3\n0.01,150e3\n";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cd.csv: no column eps_v") && Catch::Contains("[[experiment]] 1"));
  }
  SECTION("a column with no range") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0\n0.01,150e3,0\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.csv: column eps_v has the same value 0 in every reading"));
  }
}

TEST_CASE("A column the model does not produce names the key", "[calibration]") {
  Setup setup;
  setup.experiment =
      "programme = \"cd.toml\"\ndata = \"cd.csv\"\nagainst = \"eps_a\"\nmatch = [\"q\", \"void_ratio\"]\n";
  CHECK_THAT(refusal(setup),
             Catch::Contains("cal.toml: [experiment 1] match: \"void_ratio\" is not a column the "
                             "model produces"));
}

TEST_CASE("Bounds: reversed, a start outside, a key the model lacks, a bound the model refuses",
          "[calibration]") {
  Setup setup;
  SECTION("reversed") {
    setup.parameters = "parameters = { friction_angle = [40, 20] }";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [fit] parameters.friction_angle = [40, 20]: the bounds are "
                               "reversed"));
  }
  SECTION("start outside") {
    setup.parameters = "parameters = { friction_angle = [35, 40] }";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [fit] parameters.friction_angle = [35, 40]: the start 30") &&
                   Catch::Contains("not strictly inside the bounds"));
  }
  SECTION("not a parameter of the model") {
    setup.parameters = "parameters = { compression_index = [0.1, 0.3] }";
    CHECK_THAT(refusal(setup), Catch::Contains("cal.toml: [fit] parameters.compression_index: not a numeric "
                                               "parameter of drucker-prager"));
  }
  SECTION("an array element past its end, or named other than NAME(N)") {
    setup.material = "model = \"umat\"\nlibrary = \"" + std::string(SOILSPH_UMAT_LIBRARY) +
                     "\"\nname = \"drucker-prager\"\nprops = [20e6, 0.3, 30, 5000, 5]\nstate_variables = 4\n"
                     "density = 1900\n";
    for (const std::string key : {"props(6)", "props(0)", "props[3]", "props"}) {
      setup.parameters = "parameters = { \"" + key + "\" = [20, 40] }";
      const std::string refused = "cal.toml: [fit] parameters." + key + ": not a numeric parameter of umat";
      CHECK_THAT(refusal(setup), Catch::Contains(refused) && Catch::Contains("props(1) to props(5)"));
    }
  }
  SECTION("a bound outside the model's range") {
    setup.parameters = "parameters = { friction_angle = [20, 95] }";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [fit] parameters.friction_angle: the bound 95 is refused") &&
                   Catch::Contains("[material] friction_angle = 95 is out of range"));
  }
  SECTION("not a pair of numbers") {
    setup.parameters = "parameters = { friction_angle = [20, \"40\"] }";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [fit] parameters.friction_angle must be [lower, upper]"));
  }
}

TEST_CASE("An experiment the model cannot run is named with the driver's message", "[calibration]") {
  Setup setup;
  SECTION("a stress beyond failure") {
    setup.programme =
        "[initial]\np = 100000\n[[leg]]\nincrements = 20\nstress = { xx = 5e6, yy = \"hold\", zz = "
        "\"hold\" }\n";
    setup.experiment =
        "programme = \"cd.toml\"\ndata = \"cd.csv\"\nagainst = \"sig_a\"\nmatch = [\"eps_a\"]\n";
    setup.data = "sig_a,eps_a\n2e5,0.001\n3e5,0.002\n4e5,0.004\n5e5,0.01\n";
    const std::string message = refusal(setup);
    CHECK_THAT(message, Catch::Contains("cal.toml: [[experiment]] 1 (cd): ") && Catch::Contains("leg 1"));
  }
  SECTION("readings beyond the programme's reach") {
    setup.data = "eps_a,q,eps_v\n0.005,90e3,0.001\n0.01,150e3,0.0015\n0.05,180e3,0.0015\n";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [[experiment]] 1 (cd): the readings' eps_a from 0.005 to "
                               "0.05 go beyond the run's, 0 to 0.02"));
  }
  SECTION("a programme error is the programme file's") {
    setup.programme = "[initial]\np = -5\n[[leg]]\nstrain = { xx = 0.02 }\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cd.toml: [initial] p = -5 is out of range"));
  }
}

TEST_CASE("Unknown keys and missing tables name the file and key", "[calibration]") {
  Setup setup;
  SECTION("unknown experiment key") {
    setup.experiment += "wieght = 2\n";
    CHECK_THAT(refusal(setup), Catch::Contains("cal.toml: [experiment 1] wieght"));
  }
  SECTION("a missing data file") {
    setup.experiment =
        "programme = \"cd.toml\"\ndata = \"nothere.csv\"\nagainst = \"eps_a\"\nmatch = [\"q\"]\n";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [experiment 1] data: \"nothere.csv\": no such file"));
  }
  SECTION("a bad stress unit") {
    setup.experiment += "stress_unit = \"psi\"\n";
    CHECK_THAT(refusal(setup),
               Catch::Contains("cal.toml: [experiment 1] stress_unit = \"psi\" is not allowed"));
  }
}

TEST_CASE("Units: kPa stresses and percent strains read as SI", "[calibration]") {
  const TempDir dir;
  const std::string path = dir.file("d.csv", "eps_a,q\n0.5,90\n1.0,150\n");
  const MeasuredCurve curve =
      read_measured_curve(path, "eps_a", {"q"}, {.stress = 1e3, .strain = 0.01}, "test");
  CHECK(curve.driven == std::vector<double>{0.005, 0.01});
  CHECK(curve.columns[0] == std::vector<double>{90e3, 150e3});
  CHECK(curve.lines == std::vector<int>{2, 3});
}
