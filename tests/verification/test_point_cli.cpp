// `soilsph point` end to end: the CSV contract (header comment, columns, one row per increment)
// and non-zero exits with a message for invalid options and files.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "soilsph/version.h"
#include "../common/temp_dir.h"

namespace {
namespace fs = std::filesystem;

const std::string kExe = SOILSPH_EXECUTABLE;
const std::string kSource = SOILSPH_SOURCE_DIR;

/// Runs `soilsph ARGS` with stderr to `log`; returns the exit status.
int run_soilsph(const std::string& args, const fs::path& log) {
  const std::string command = kExe + " " + args + " > /dev/null 2> " + log.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
/// Runs `soilsph point ARGS` with stderr to `log`; returns the exit status.
int point(const std::string& args, const fs::path& log) {
  return run_soilsph("point " + args, log);
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  soilsph::testing::TempDir unique{"soilsph-point-cli"};
  const fs::path& path = unique.path();
};
}  // namespace

TEST_CASE("soilsph point writes the contract CSV", "[cli]") {
  TempDir dir;
  const fs::path out = dir.path / "curve.csv";
  const std::string material = kSource + "/data/materials/mcc-table1.toml";
  const std::string test = GENERATE("triaxial-drained", "triaxial-undrained", "oedometer", "isotropic");
  REQUIRE(point(material + " --test " + test + " --strain-max 0.02,0.01 --increments 5 --ocr 2 --out " +
                    out.string(),
                dir.path / "log") == 0);
  // Without --integrator the material's integrator key runs (the shipped file says explicit).
  CHECK(read(out).find("\n# integrator: explicit (the material's integrator key)\n") != std::string::npos);
  std::istringstream csv(read(out));
  std::string line;
  REQUIRE(std::getline(csv, line));
  CHECK(line.rfind("# ", 0) == 0);
  CHECK(line.find("compression-positive") != std::string::npos);
  CHECK(line.find(',') == std::string::npos);  // a comment line that CSV readers do not split
  while (std::getline(csv, line) && line.starts_with("# ")) {
  }
  CHECK(line == "eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u,tau_xy,gamma_xy");
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') == 11);
  }
  CHECK(rows == 11);  // initial state + 2 legs × 5 increments
}

TEST_CASE("soilsph point runs a strain-path file and the cvode reference", "[cli]") {
  TempDir dir;
  const fs::path path = dir.path / "path.csv";
  std::ofstream(path) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n-1e-3,5e-4,5e-4,0,0,1e-4\n-1e-3,5e-4,5e-4,0,0,0\n";
  const std::string material = kSource + "/data/materials/dp-table1.toml";
  CHECK(point(material + " --test strain-path --strain-path " + path.string() + " --integrator cvode --out " +
                  (dir.path / "a.csv").string(),
              dir.path / "log") == 0);
  CHECK(point(material + " --test strain-path:" + path.string() + " --out " + (dir.path / "b.csv").string(),
              dir.path / "log") == 0);
  std::istringstream csv(read(dir.path / "b.csv"));
  int rows = 0;
  for (std::string line; std::getline(csv, line);) rows += !line.starts_with("#");
  CHECK(rows == 1 + 3);  // the column header, the initial state and one row per increment
}

TEST_CASE("soilsph point rejects invalid options and files with a message", "[cli]") {
  TempDir dir;
  const fs::path log = dir.path / "log";
  const std::string material = kSource + "/data/materials/mcc-table1.toml";
  const fs::path bad_path = dir.path / "bad.csv";
  std::ofstream(bad_path) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n0,0,0,0,0\n";
  const fs::path bad_material = dir.path / "bad.toml";
  std::ofstream(bad_material) << "[material]\nmodel = \"modified-cam-clay\"\n";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {material + " --test triaxial", "unknown test"},
      {material + " --test isotropic --ocr 0.5", "ocr"},
      {material + " --test isotropic --increments 0", "increments"},
      {material + " --test isotropic --integrator nonsense", "nonsense"},
      {material + " --test oedometer --strain-max 0.1,0.1", "zero length"},
      {material + " --test strain-path", "--strain-path"},
      {material + " --test strain-path --strain-path " + bad_path.string(), "bad.csv:2"},
      {material + " --test isotropic --strain-path " + bad_path.string(), "strain-path"},
      {material + " --test strain-path:" + bad_path.string() + " --increments 3", "do not apply"},
      {bad_material.string() + " --test isotropic", "density"},
      {material + " --test isotropic --out /nonexistent/dir/out.csv", "/nonexistent/dir/out.csv"},
      {dir.path.string() + "/missing.toml --test isotropic", "missing.toml"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    const int status = point(c.args, log);
    // Input errors exit 2; an output file that cannot be opened is a failed run, 1.
    CHECK(status == (c.message == "/nonexistent/dir/out.csv" ? 1 : 2));
    CHECK(read(log).find(c.message) != std::string::npos);
  }
}

TEST_CASE("soilsph point states the allowed range of each option in plain numbers (exit 2)", "[cli]") {
  TempDir dir;
  const fs::path log = dir.path / "log";
  const std::string mcc = kSource + "/data/materials/mcc-table1.toml";
  const std::string dp = kSource + "/data/materials/dp-table1.toml";
  const fs::path steep = dir.path / "steep.csv";
  std::ofstream(steep) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n0.5,0,0,0,0,0\n-10,0,0,0,0,0\n";
  const fs::path drift = dir.path / "drift.csv";
  std::ofstream(drift) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n0,0,0,0.6,0,0\n# twice\n0,0,0,0.6,0,0\n";
  const fs::path broken = dir.path / "broken.toml";
  std::ofstream(broken) << "material = \"" << mcc
                        << "\"\n[initial]\np = 1__0\n[[leg]]\nstrain = { xx = 0.1 }\n";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {mcc + " --test isotropic --p-initial 0",
       "--p-initial: 0 is out of range (allowed: 1 <= value <= 1e12 Pa)"},
      {mcc + " --test isotropic --p-initial 1e300", "--p-initial: 1e300 is out of range"},
      {mcc + " --test isotropic --ocr 0.5", "--ocr: 0.5 is out of range (allowed: 1 <= value < 1e6)"},
      {mcc + " --test isotropic --strain-max 1e6",
       "--strain-max: 1e6 is out of range (allowed: -1 < value < 1)"},
      {mcc + " --test isotropic --strain-max 0.1,-2", "--strain-max: -2 is out of range"},
      {mcc + " --test isotropic --strain-max 1", "--strain-max: 1 is out of range"},
      {mcc + " --test isotropic --strain-max 0.1,,0.2", "--strain-max: an empty item in 0.1,,0.2"},
      {mcc + " --test isotropic --strain-max 0.1,", "--strain-max: an empty item in 0.1,"},
      {mcc + " --test isotropic --increments 2.5",
       "--increments: 2.5 is not a whole number (allowed: 1 <= value <= 1e6)"},
      {mcc + " --test isotropic --increments 1e7",
       "--increments: 1e7 is out of range (allowed: 1 <= value <= 1e6)"},
      {mcc + " --test strain-path:" + steep.string(),
       "steep.csv:3: d_xx = -10 is out of range (allowed: -1 < value < 1)"},
      {mcc + " --test strain-path:" + drift.string(),
       "drift.csv:4: eps_xy accumulated up to this row = 1.2 is out of range (allowed: -1 < value < 1)"},
      {mcc + " --test isotropic --set foo.bar=1",
       "--set foo.bar=1: soilsph point reads only the [material] table"},
      {mcc + " --test isotropic --set material.young_modulus=-5",
       "--set material.young_modulus=-5: [material] young_modulus = -5 is out of range (allowed: 1 <= value "
       "<= 1e12 Pa)"},
      {dp + " --test isotropic --ocr 2", "--ocr 2: OCR applies to modified-cam-clay only"},
      {mcc + " --test triaxial-drained --integrator rk4", "--integrator rk4: unknown integrator"},
      {mcc + " --test triaxial-drained --integrator ''", "--integrator \"\": unknown integrator"},
      {mcc + " --test triaxial-drained --set material.=1",
       "--set material.=1: an empty name in the key path"},
      // Without --test the file must be a programme: a material file, or a programme with a syntax error,
      // is named (an input-fuzzer finding: the error said only that --test was missing).
      {mcc, "mcc-table1.toml: no [[leg]] table, so not a programme file"},
      {broken.string(), "broken.toml:3:"},
  };
  for (const Case& c : cases) {
    INFO(c.args);
    CHECK(point(c.args, log) == 2);
    const std::string message = read(log);
    CHECK(message.find(c.message) != std::string::npos);
    CHECK(std::count(message.begin(), message.end(), '\n') <= 2);  // CLI11 adds "Run with --help"
  }
  // OCR 1 is every model's state; the increments may be written as 1e1.
  CHECK(point(dp + " --test isotropic --ocr 1 --increments 1e1", log) == 0);
}

// Runs that fail or lose meaning exit 1, naming the material, the integrator that ran and the
// increment in the user's terms. The expected increments follow from the MCC normal compression line
// with pressure-dependent elasticity, which the implicit return follows exactly on an isotropic path:
// p = p0 exp(eps_v (1+e0)/lambda) passes 1e12 Pa from p0 = 100 kPa at
// eps_v = 0.085/1.68 ln(1e7) = 0.8155, i.e. in increment 9 of 10 to eps_v = 0.999, and in the third row
// of a path adding eps_v = 0.3 per row.
TEST_CASE("soilsph point names the increment, row and integrator of a run that fails (exit 1)", "[cli]") {
  TempDir dir;
  const fs::path log = dir.path / "log";
  // The material's integrator key says explicit, which passes 1e12 Pa elsewhere: run implicit.
  const std::string mcc = kSource +
                          "/data/materials/mcc-table1.toml --integrator implicit --set "
                          "material.elasticity=pressure-dependent";
  CHECK(point(mcc + " --test isotropic --strain-max 0.999 --increments 10", log) == 1);
  CHECK(
      read(log).find("mcc-table1.toml (modified-cam-clay, --integrator implicit): increment 9 of 10 of leg 1 "
                     "(eps_v from 0 to 0.999): the result has lost meaning: ") != std::string::npos);
  const fs::path path = dir.path / "compress.csv";
  std::ofstream(path) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n# 0.3 in eps_v per row\n"
                      << "-0.1,-0.1,-0.1,0,0,0\n-0.1,-0.1,-0.1,0,0,0\n-0.1,-0.1,-0.1,0,0,0\n";
  CHECK(point(mcc + " --test strain-path:" + path.string(), log) == 1);
  CHECK(read(log).find("compress.csv:5: the result has lost meaning: ") != std::string::npos);
  // A 99.9 % extension in one increment at E = 1e12 Pa: substep's error control gives up and its
  // implicit fallback does not converge either; the message is substep's, not the fallback's.
  const std::string stiff = kSource + "/data/materials/mcc-table1.toml --set material.young_modulus=1e12";
  CHECK(point(stiff + " --test oedometer --strain-max -0.999 --increments 1 --integrator substep", log) == 1);
  const std::string message = read(log);
  CHECK(message.find(
            "(modified-cam-clay, --integrator substep): increment 1 of 1 of leg 1 (eps_a from 0 to -0.999): "
            "substep: ") != std::string::npos);
  CHECK(std::count(message.begin(), message.end(), '\n') == 1);
}

TEST_CASE("soilsph material gives one line for a derived constant that overflows (exit 2)", "[cli]") {
  TempDir dir;
  const fs::path material = dir.path / "loose.toml";
  std::ofstream(material)
      << "[material]\nmodel = \"modified-cam-clay\"\ndensity = 2000.0\npoisson_ratio = 0.3\n"
         "friction_angle = 35.0\ncompression_index = 0.085\nswelling_index = 0.019\n"
         "initial_void_ratio = 1e308\n";
  const fs::path log = dir.path / "log";
  CHECK(run_soilsph("material " + material.string(), log) == 2);
  const std::string message = read(log);
  CHECK(message.find(
            "loose.toml: [material] initial_void_ratio = 1e308 gives (1+e0)/(lambda-kappa) (eq 27) = inf") !=
        std::string::npos);
  CHECK(std::count(message.begin(), message.end(), '\n') == 1);
}

TEST_CASE("a viscoplastic relaxation time: material prints G tau, point warns that it does not apply",
          "[cli]") {
  TempDir dir;
  const fs::path material = dir.path / "viscous.toml";
  std::ofstream(material)
      << "[material]\nmodel = \"drucker-prager\"\ndensity = 2000.0\nyoung_modulus = 2.6e6\n"
         "poisson_ratio = 0.3\nfriction_angle = 30.0\nviscoplastic_relaxation_time = 1e-3\n";
  // G = E / (2(1 + ν)) = 1 MPa, so G τ = 1000 Pa s.
  const fs::path out = dir.path / "out";
  REQUIRE(std::system((kExe + " material " + material.string() + " > " + out.string()).c_str()) == 0);
  CHECK(read(out).find("slow-flow viscosity G tau = 1000 Pa s") != std::string::npos);
  const fs::path log = dir.path / "log";
  REQUIRE(point(material.string() + " --test triaxial-drained --strain-max 0.01 --increments 2 --out " +
                    (dir.path / "curve.csv").string(),
                log) == 0);
  CHECK(read(log).find("viscoplastic_relaxation_time is ignored here: the material-point driver is "
                       "rate-independent") != std::string::npos);
}

// The header names everything needed to run the curve again; the material line is TOML that reads
// back to the material the run used (the file after --set, the integrator that ran, defaults filled).
TEST_CASE("soilsph point records version, command, material, integrator and test in its header", "[cli]") {
  TempDir dir;
  const fs::path out = dir.path / "curve.csv";
  const std::string material = kSource + "/data/materials/mcc-table1.toml";
  const std::string args =
      material + " --test triaxial-drained --p-initial 50e3 --ocr 2 --strain-max 0.02,0.01 " +
      "--increments 5 --integrator substep --set material.friction_angle=30 --out " + out.string();
  REQUIRE(point(args, dir.path / "log") == 0);
  std::istringstream csv(read(out));
  std::vector<std::string> comments;
  for (std::string line; std::getline(csv, line) && line.starts_with("# ");)
    comments.push_back(line.substr(2));
  REQUIRE(comments.size() == 7);
  CHECK(comments[1] == std::string("soilsph ") + soilsph::kVersion);
  CHECK(comments[2] == "command: soilsph point " + args);
  CHECK(comments[4] == "integrator: substep");
  CHECK(comments[5] ==
        "test: triaxial-drained; p_initial = 50000 Pa; ocr = 2; eps_a targets 0.02 0.01 (5 increments each)");
  // MCC's failure line is its CSL, M = 6 sin 30° / (3 − sin 30°) = 1.2 (eq 26) with φ set to 30°.
  const std::string line = "failure line (triaxial compression): q = slope p' + intercept; slope = ";
  REQUIRE(comments[6].starts_with(line));
  CHECK(std::stod(comments[6].substr(line.size())) == Approx(1.2).epsilon(1e-14));
  CHECK(comments[6].ends_with("; intercept = 0 Pa"));
  const std::string prefix = "material: " + material + " with --set: ";
  REQUIRE(comments[3].starts_with(prefix));
  std::string table = "[material]\n" + comments[3].substr(prefix.size());
  for (std::size_t at; (at = table.find("; ")) != std::string::npos;) table.replace(at, 2, "\n");
  const toml::table root = toml::parse(table);
  const soilsph::Material recorded =
      soilsph::read_material(soilsph::TableReader(*root["material"].as_table(), "header", "material"));
  soilsph::ModifiedCamClay::Params expected =
      std::get<soilsph::ModifiedCamClay>(soilsph::load_material(material)).params();
  expected.friction_angle = 30.0;
  expected.integrator = soilsph::Integrator::Substep;
  const auto& got = std::get<soilsph::ModifiedCamClay>(recorded).params();
  CHECK(got.friction_angle == expected.friction_angle);
  CHECK(got.integrator == expected.integrator);
  CHECK(got.young_modulus == expected.young_modulus);
  CHECK(got.elasticity == expected.elasticity);
  CHECK(got.compression_index == expected.compression_index);
  CHECK(got.swelling_index == expected.swelling_index);
  CHECK(got.initial_void_ratio == expected.initial_void_ratio);
  CHECK(got.poisson_ratio == expected.poisson_ratio);
  CHECK(got.density == expected.density);
  CHECK(got.substep_tolerance == expected.substep_tolerance);
  CHECK(got.implicit_alpha == expected.implicit_alpha);

  // A strain path is named with its row count.
  const fs::path path = dir.path / "path.csv";
  std::ofstream(path) << "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n-1e-3,5e-4,5e-4,0,0,0\n-1e-3,5e-4,5e-4,0,0,0\n";
  REQUIRE(
      point(material + " --test strain-path:" + path.string() + " --integrator cvode --out " + out.string(),
            dir.path / "log") == 0);
  const std::string header = read(out);
  CHECK(header.find("\n# test: strain-path; p_initial = 100000 Pa; ocr = 1; strain path " + path.string() +
                    " (2 rows; one increment each)\n") != std::string::npos);
  CHECK(header.find("\n# integrator: cvode (the CVODE reference") != std::string::npos);
}

TEST_CASE("soilsph point --path-tolerance: recorded in the header, one row per increment, range checked",
          "[cli][path-substeps]") {
  TempDir dir;
  const fs::path out = dir.path / "curve.csv", log = dir.path / "log";
  const std::string material = kSource + "/data/materials/mcc-table1.toml";
  const std::string base =
      material + " --test triaxial-drained --strain-max 0.02 --increments 4 --integrator implicit";
  REQUIRE(point(base + " --path-tolerance 1e-5 --out " + out.string(), log) == 0);
  const std::string csv = read(out);
  CHECK(csv.find("\n# driver sub-steps: path_tolerance = 0.00001 (") != std::string::npos);
  std::istringstream rows(csv);
  int data_rows = -1;  // the column row
  for (std::string line; std::getline(rows, line);)
    if (!line.starts_with("#")) ++data_rows;
  CHECK(data_rows == 5);  // the initial state and 4 increments
  // Without the option the header says nothing of sub-steps (the file of a plain run).
  REQUIRE(point(base + " --out " + out.string(), log) == 0);
  CHECK(read(out).find("sub-steps") == std::string::npos);
  CHECK(point(base + " --path-tolerance 0.5", log) == 2);
  CHECK(read(log).find("--path-tolerance: 0.5 is out of range (allowed: 1e-12 <= value <= 0.01)") !=
        std::string::npos);
  CHECK(point(material + " --test triaxial-drained --integrator cvode --path-tolerance 1e-4", log) == 2);
  CHECK(read(log).find("--path-tolerance does not apply to --integrator cvode") != std::string::npos);
}

TEST_CASE("soilsph point: a stress leg past the strength writes the curve up to there and says why",
          "[cli]") {
  // D-P (Table 1, φ = 30°), drained from p' = 100 kPa: σ_a raised to 500 kPa with σ_r held, past the
  // strength σ_a = 100 kPa · (1 + q_f/σ_r) that the failure line gives (about 300 kPa).
  TempDir dir;
  const fs::path programme = dir.path / "past-strength.toml";
  std::ofstream(programme) << "material = \"" << kSource << "/data/materials/dp-table1.toml\"\n"
                           << "[initial]\np = 100e3\n"
                           << "[[leg]]\nname = \"drained to 500 kPa\"\nincrements = 40\n"
                           << "stress = { xx = 500e3, yy = \"hold\", zz = \"hold\" }\n";
  const fs::path out = dir.path / "curve.csv";
  CHECK(point(programme.string() + " --set material.friction_angle=30 --out " + out.string(),
              dir.path / "log") == 1);
  const std::string log = read(dir.path / "log");
  INFO(log);
  CHECK(log.find("at or beyond the soil's strength") != std::string::npos);
  CHECK(log.find("drained to 500 kPa") != std::string::npos);
  CHECK(log.find("more increments may help") == std::string::npos);
  const std::string csv = read(out);
  CHECK(csv.find("\n# stopped: ") != std::string::npos);
  // The header line and the rows up to the last completed increment: fewer than 1 + 40.
  std::size_t rows = 0;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty() && line[0] != '#' && line.rfind("eps_a", 0) != 0) ++rows;
  CHECK(rows > 1);
  CHECK(rows < 41);
}
