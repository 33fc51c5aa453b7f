// Programme files and undrained legs: the shipped programmes against the CVODE reference and their
// own imposed conditions, undrained linear elasticity against Hooke's law, the K0 initial state
// against its formulas, the built-in tests as programmes, and the reader's refusals.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "constitutive/parameters.h"
#include "../common/material_toml.h"
#include "../common/temp_dir.h"
#include "verification/programme/programme_file.h"

using namespace soilsph;
using namespace soilsph::verification;
using Catch::Contains;

namespace {
const std::string kSource = SOILSPH_SOURCE_DIR;

/// Largest difference of p, q and eps_v along two curves, relative to the largest |p|, |q| or 1e-3.
double curve_difference(const PointCurve& a, const PointCurve& b) {
  REQUIRE(a.size() == b.size());
  double stress = 1.0, diff_stress = 0.0, diff_strain = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    stress = std::max({stress, std::abs(b[i].p), std::abs(b[i].q), std::abs(b[i].tau_xy)});
    diff_stress = std::max({diff_stress, std::abs(a[i].p - b[i].p), std::abs(a[i].q - b[i].q),
                            std::abs(a[i].tau_xy - b[i].tau_xy), std::abs(a[i].u - b[i].u)});
    diff_strain = std::max(diff_strain, std::abs(a[i].eps_v - b[i].eps_v));
  }
  return std::max(diff_stress / stress, diff_strain / 1e-3);
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  static const soilsph::testing::TempDir dir("soilsph-programme");  // one per test process
  const auto path = dir / (name + ".toml");
  std::ofstream(path) << text;
  return path;
}

const std::string& kLinear = fixtures::kLinearElasticToml;
}  // namespace

TEST_CASE("every shipped programme runs with implicit and with CVODE, and they agree", "[programme]") {
  for (const auto& entry : std::filesystem::directory_iterator(kSource + "/data/programmes")) {
    const std::string path = entry.path().string();
    INFO(path);
    const ProgrammeFile file = read_programme_file(path);
    const PointCurve reference = run_programme(file.material, file.programme, "cvode");
    const PointCurve implicit = run_programme(file.material, file.programme, "implicit");
    CHECK(curve_difference(implicit, reference) < 2e-2);
    // What every leg imposes holds at its end in both runs.
    for (const PointCurve* curve : {&reference, &implicit}) {
      const PointRecord& last = curve->back();
      if (path.find("cu-triaxial") != std::string::npos) {
        CHECK(last.eps_a == Approx(0.15).margin(1e-12));
        CHECK(std::abs(last.eps_v) < 1e-12);                   // undrained: the volume is held
        CHECK(last.sig_r + last.u == Approx(curve->front().sig_r).epsilon(1e-9));  // cell pressure held
      } else if (path.find("oedometer") != std::string::npos) {
        CHECK(last.sig_a == Approx(800e3).epsilon(1e-9));
        CHECK(last.eps_r == 0.0);
      } else if (path.find("simple-shear") != std::string::npos) {
        CHECK(last.gamma_xy == Approx(-0.01).margin(1e-12));
        CHECK(last.sig_a == Approx(100e3).epsilon(1e-9));
        CHECK(curve->size() == 1 + 5 * 2 * 50);
      } else if (path.find("after-k0") != std::string::npos) {
        CHECK(last.eps_a == Approx(0.1).margin(1e-12));
        CHECK(last.sig_r == Approx(100e3 * (*curve)[40].sig_r / (*curve)[40].sig_a).epsilon(1e-9));
      }
    }
  }
}

TEST_CASE("undrained linear elasticity: p' constant, q = 3G eps_a, u = q/3 (Hooke's law)", "[programme]") {
  const std::string text = kLinear + R"(
[initial]
p = 100e3
[[leg]]
drainage = "undrained"
increments = 10
strain = { xx = 0.02 }
stress = { yy = "hold", zz = "hold" }
)";
  const ProgrammeFile file = read_programme_file(write_file("hooke", text).string());
  const double G = 1.0e6 / (2.0 * 1.3);
  for (const char* integrator : {"implicit", "cvode"}) {
    const PointRecord last = run_programme(file.material, file.programme, integrator).back();
    CHECK(last.eps_v == Approx(0.0).margin(1e-15));
    CHECK(last.p == Approx(100e3).epsilon(1e-9));
    CHECK(last.q == Approx(3.0 * G * 0.02).epsilon(1e-9));
    CHECK(last.u == Approx(G * 0.02).epsilon(1e-9));
  }
}

TEST_CASE("the K0 initial state: Jaky's K0 times OCR^sin(phi), p_c through the state times OCR", "[programme]") {
  const std::string text = R"(
material = ")" + kSource + R"(/data/materials/mcc-table1.toml"
[initial]
vertical_stress = 80e3
ocr = 2
[[leg]]
increments = 1
stress = { xx = "hold" }
)";
  const ProgrammeFile file = read_programme_file(write_file("k0", text).string());
  const double s = std::sin(35.0 * std::numbers::pi / 180.0), M = 6.0 * s / (3.0 - s);
  const double k0 = (1.0 - s) * std::pow(2.0, s);
  const PointRecord first = run_programme(file.material, file.programme, "implicit").front();
  CHECK(first.sig_a == Approx(80e3));
  CHECK(first.sig_r == Approx(k0 * 80e3));
  const double p = 80e3 * (1.0 + 2.0 * k0) / 3.0, q = 80e3 * (1.0 - k0);
  CHECK(first.p_c == Approx(2.0 * (p + q * q / (M * M * p))));
}

TEST_CASE("a built-in test is a programme: --test and its programme file give the same curve", "[programme]") {
  PointTest test;
  test.path = LoadPath::TriaxialUndrained;
  test.p_initial = 150e3;
  test.ocr = 1.5;
  test.strain_targets = {0.05, 0.02};
  test.increments = 20;
  const std::string text = R"(
material = ")" + kSource + R"(/verification/cases/materials/mcc-pressure-dependent.toml"
[initial]
p = 150e3
ocr = 1.5
[[leg]]
drainage = "undrained"
increments = 20
strain = { xx = [0.05, 0.02] }
stress = { yy = "hold", zz = "hold" }
)";
  const ProgrammeFile file = read_programme_file(write_file("builtin", text).string());
  const PointCurve a = run_point_test(file.material, test, "implicit");
  const PointCurve b = run_programme(file.material, file.programme, "implicit");
  CHECK(curve_difference(a, b) < 1e-12);
}

TEST_CASE("a programme file may ask for driver sub-steps (path_tolerance), within their range", "[programme]") {
  const std::string legs = "\n[initial]\np = 100e3\n[[leg]]\nstrain = { xx = 0.01 }\nstress = { yy = \"hold\" }\n";
  CHECK(read_programme_file(write_file("pt", kLinear + legs).string()).programme.path_tolerance == 0.0);
  // A top-level key: before the first table.
  CHECK(read_programme_file(write_file("pt", "path_tolerance = 1e-5\n" + kLinear + legs).string())
            .programme.path_tolerance == 1e-5);
  CHECK(read_programme_file(write_file("pt", "path_tolerance = 0\n" + kLinear + legs).string())
            .programme.path_tolerance == 0.0);
  const std::string too_large = write_file("pt", "path_tolerance = 0.5\n" + kLinear + legs).string();
  CHECK_THROWS_WITH(read_programme_file(too_large),
                    Contains(too_large + ": path_tolerance = 0.5 is out of range (allowed: 0 (off) or 1e-12"));
  const std::string word = write_file("pt", "path_tolerance = \"fine\"\n" + kLinear + legs).string();
  CHECK_THROWS_WITH(read_programme_file(word), Contains("path_tolerance must be a number"));
}

TEST_CASE("a programme file's mistakes are named with the file, the leg and the key", "[programme]") {
  struct Case {
    std::string body, message;
  };
  const std::string initial = "\n[initial]\np = 100e3\n";
  const Case cases[] = {
      {initial + "[[leg]]\ndrainage = \"undrained\"\nstrain = { xx = 0.1 }\n",
       "[leg 1] an undrained leg needs a stress on a normal component"},
      {initial + "[[leg]]\nstrain = { xq = 0.1 }\n", "[leg 1] strain.xq is not a component"},
      {initial + "[[leg]]\nstrain = { xx = 0.1 }\nstress = { xx = 1e5 }\n", "strain and a stress"},
      {initial + "[[leg]]\nstrain = { xx = [0.1, 0.2], xy = [0.1] }\nstress = { yy = [1, 2, 3] }\n",
       "a list of 3 targets where another has 2"},
      {initial + "[[leg]]\nstrain = { xx = 1.5 }\n", "strain.xx = 1.5 is out of range (allowed: -1 < value < 1)"},
      {initial + "[[leg]]\nstress = { xx = \"keep\" }\n", "stress.xx must be a number, \"hold\" or a list"},
      {initial + "[[leg]]\nincrements = 0\nstrain = { xx = 0.1 }\n", "[leg 1] increments"},
      {initial + "[[leg]]\ndrainage = \"partial\"\n", "[leg 1] drainage"},
      {initial + "ocr = 2\n[[leg]]\nstrain = { xx = 0.1 }\n", "[initial] ocr: applies to models with a preconsolidation"},
      {"\n[initial]\np = 1e5\nvertical_stress = 1e5\n[[leg]]\n", "give either p (isotropic) or vertical_stress"},
      {initial + "[[leg]]\nspeed = 1\n", "[leg 1] speed"},
      {initial, "no [[leg]] tables"},
  };
  for (const Case& c : cases) {
    INFO(c.body);
    const std::string path = write_file("bad", kLinear + c.body).string();
    CHECK_THROWS_AS(read_programme_file(path), ParameterError);
    CHECK_THROWS_WITH(read_programme_file(path), Contains(c.message) && Contains(path));
  }
}
