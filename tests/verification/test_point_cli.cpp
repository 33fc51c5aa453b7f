// `soilsph point` end to end: the CSV contract (header comment, columns, one row per increment)
// and non-zero exits with a message for invalid options and files.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {
namespace fs = std::filesystem;

const std::string kExe = SOILSPH_EXECUTABLE;
const std::string kSource = SOILSPH_SOURCE_DIR;

/// Runs `soilsph point ARGS` with stderr to `log`; returns the exit status.
int point(const std::string& args, const fs::path& log) {
  const std::string command = kExe + " point " + args + " > /dev/null 2> " + log.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("soilsph_point_cli_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
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
  std::istringstream csv(read(out));
  std::string line;
  REQUIRE(std::getline(csv, line));
  CHECK(line.rfind("# ", 0) == 0);
  CHECK(line.find("compression-positive") != std::string::npos);
  CHECK(line.find(',') == std::string::npos);  // a comment line that CSV readers do not split
  REQUIRE(std::getline(csv, line));
  CHECK(line.rfind("eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u", 0) == 0);
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    CHECK(std::count(line.begin(), line.end(), ',') == 9);
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
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  CHECK(lines == 2 + 3);
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
    CHECK(point(c.args, log) != 0);
    CHECK(read(log).find(c.message) != std::string::npos);
  }
}
