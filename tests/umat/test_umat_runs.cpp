// UMAT plug-ins in whole runs of the executable (a child process each): a UMAT that crashes or stops
// the process is named with its call, and a collapse writes the UMAT's state variables into its frames.
#include <hdf5.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../common/temp_dir.h"
#include "tests/fault/child_process.h"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using soilsph::test::run_child;

namespace {

using soilsph::testing::TempDir;

const std::string kMisbehaving = SOILSPH_UMAT_MISBEHAVING_C;

/// The C test UMAT (tests/umat/misbehaving.c) under CMNAME `name`, as a [material] table.
std::string misbehaving(const std::string& name) {
  return "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" + kMisbehaving +
         "\"\nsymbol = \"umat_elastic_c\"\nname = \"" + name + "\"\nprops = [1.0e6, 0.3]\n";
}

/// The paper's column at 4 mm (176 particles) up to `end_time`, with `material`.
std::string column(double end_time, const std::string& material) {
  return "[scene]\ncolumn_width = 0.04\ncolumn_height = 0.06\nparticle_spacing = 0.004\nsmoothing_ratio = "
         "1.3\n"
         "end_time = " +
         std::to_string(end_time) + "\ngravity = 9.81\nwall_withdrawal = \"instant\"\n" + material +
         "[output]\nframe_interval = 0.005\n";
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

/// A dataset of doubles of an HDF5 file.
std::vector<double> read_doubles(const fs::path& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  std::vector<double> values;
  if (H5Lexists(f, name.c_str(), H5P_DEFAULT) > 0) {
    const hid_t set = H5Dopen2(f, name.c_str(), H5P_DEFAULT), space = H5Dget_space(set);
    values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(set);
  }
  H5Fclose(f);
  return values;
}

}  // namespace

TEST_CASE("A UMAT that stops the process (Fortran STOP) in `point` is named with its call", "[umat]") {
  const TempDir temp("soilsph-umat-runs");
  std::ofstream(temp.path() / "stop.toml") << misbehaving("STOP");
  const auto r =
      run_child({SOILSPH_EXECUTABLE, "point", (temp.path() / "stop.toml").string(), "--test",
                 "triaxial-drained", "--strain-max", "0.01", "--out", (temp.path() / "c.csv").string()},
                temp.path() / "log");
  CAPTURE(r.log);
  CHECK(r.exit_status == 1);  // exit(0) inside the call would have passed for success
  CHECK_THAT(r.log, Contains(kMisbehaving) && Contains("umat_elastic_c") && Contains("ended the process") &&
                        Contains("KINC = 1"));
}

TEST_CASE("A UMAT that crashes in `collapse` stops the run with the particle and the call named", "[umat]") {
  const TempDir temp("soilsph-umat-runs");
  std::ofstream(temp.path() / "scene.toml") << column(0.01, misbehaving("SEGFAULT"));
  const auto r = run_child({SOILSPH_EXECUTABLE, "collapse", (temp.path() / "scene.toml").string(),
                            "--threads", "1", "--out", (temp.path() / "run").string()},
                           temp.path() / "log");
  CAPTURE(r.log);
  CHECK(r.signal == 0);
  CHECK(r.exit_status != 0);
  CHECK_THAT(r.log, Contains("soil particle 0") && Contains(kMisbehaving) && Contains("umat_elastic_c") &&
                        Contains("NOEL = 1") && Contains("crashed with SIGSEGV") && Contains("step 1"));
  // The frame of t = 0 stays, and summary.json says why the run stopped.
  CHECK(fs::exists(temp.path() / "run" / "frames" / "frame_000000.h5"));
  CHECK_THAT(text_of(temp.path() / "run" / "summary.json"), Contains("crashed with SIGSEGV"));
}

TEST_CASE("A collapse writes the UMAT's state variables into its frames when asked", "[umat]") {
  const TempDir temp("soilsph-umat-runs");
  // Table 1's D-P through libsoilsph_umat.so: STATEV(1) p_c (0 for D-P), STATEV(2) the accumulated
  // equivalent plastic strain, which grows where the column yields (docs/reference/umat-library.md).
  const std::string material = "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" +
                               std::string(SOILSPH_UMAT_LIBRARY) +
                               "\"\nname = \"drucker-prager\"\nprops = [1.0e6, 0.3, 35.0, 0.0, 0.0]\n"
                               "state_variables = 4\nthread_safe = true\n";
  std::ofstream(temp.path() / "scene.toml") << column(0.03, material) << "state_variables = true\n";
  const auto r = run_child({SOILSPH_EXECUTABLE, "collapse", (temp.path() / "scene.toml").string(),
                            "--threads", "1", "--out", (temp.path() / "run").string()},
                           temp.path() / "log");
  CAPTURE(r.log);
  REQUIRE(r.exit_status == 0);
  const fs::path first = temp.path() / "run" / "frames" / "frame_000000.h5",
                 last = temp.path() / "run" / "frames" / "frame_000006.h5";
  REQUIRE(fs::exists(last));
  const std::size_t n = read_doubles(last, "p").size();
  CHECK(n == 176);
  for (int k = 1; k <= 4; ++k) CHECK(read_doubles(last, "statev_" + std::to_string(k)).size() == n);
  CHECK(read_doubles(last, "statev_5").empty());
  const auto plastic_start = read_doubles(first, "statev_2"), plastic_end = read_doubles(last, "statev_2");
  CHECK(*std::max_element(plastic_start.begin(), plastic_start.end()) == 0.0);
  CHECK(*std::max_element(plastic_end.begin(), plastic_end.end()) > 1e-3);
  CHECK(*std::min_element(plastic_end.begin(), plastic_end.end()) >= 0.0);
  const auto pc = read_doubles(last, "statev_1");
  CHECK(*std::max_element(pc.begin(), pc.end()) == 0.0);
  CHECK_THAT(text_of(temp.path() / "run" / "frames.xdmf"), Contains("frame_000006/statev_4"));
  CHECK_THAT(text_of(temp.path() / "run" / "scene.toml"), Contains("state_variables = true"));
  // Without the key, no state variables.
  std::ofstream(temp.path() / "plain.toml") << column(0.005, material);
  REQUIRE(run_child({SOILSPH_EXECUTABLE, "collapse", (temp.path() / "plain.toml").string(), "--threads", "1",
                     "--out", (temp.path() / "plain").string()},
                    temp.path() / "log2")
              .exit_status == 0);
  CHECK(read_doubles(temp.path() / "plain" / "frames" / "frame_000001.h5", "statev_1").empty());
}
