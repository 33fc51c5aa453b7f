// Reading strain-path CSV files: a good file, and malformed rows rejected with file and line.
#include <catch2/catch.hpp>

#include <sstream>

#include "constitutive/parameters.h"
#include "verification/paths/strain_path_csv.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
std::vector<Mat3> parse(const std::string& text) {
  std::istringstream in(text);
  return read_strain_path(in, "path.csv").increments;
}
}  // namespace

TEST_CASE("a good strain-path file gives one symmetric tensor per row", "[strain-path]") {
  const auto increments = parse(
      "# a comment line\n"
      "d_xx, d_yy, d_zz, d_xy, d_yz, d_xz\r\n"
      "\n"
      "-1e-3,5e-4,5e-4,0,0,0\n"
      "# between rows\n"
      " 1.5e-4 , -2e-4, 3e-4, 1e-5, 2e-5, 3e-5\n");
  REQUIRE(increments.size() == 2);
  CHECK(increments[0](0, 0) == -1e-3);
  CHECK(increments[0](1, 1) == 5e-4);
  CHECK(increments[0](2, 2) == 5e-4);
  const Mat3& d = increments[1];
  CHECK(d(0, 0) == 1.5e-4);
  CHECK(d(1, 1) == -2e-4);
  CHECK(d(2, 2) == 3e-4);
  CHECK(d(0, 1) == 1e-5);
  CHECK(d(1, 0) == 1e-5);
  CHECK(d(1, 2) == 2e-5);
  CHECK(d(2, 1) == 2e-5);
  CHECK(d(0, 2) == 3e-5);
  CHECK(d(2, 0) == 3e-5);
}

TEST_CASE("malformed strain-path files are rejected naming file and line", "[strain-path]") {
  const std::string header = "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz\n";
  CHECK_THROWS_WITH(parse(header + "0,0,0,0,0,0\n1,2,3,4,5\n"),
                    Catch::Contains("path.csv:3") && Catch::Contains("expected 6 values"));
  CHECK_THROWS_WITH(parse(header + "0,0,0,0,0,0,0\n"),
                    Catch::Contains("path.csv:2") && Catch::Contains("got 7"));
  CHECK_THROWS_WITH(parse(header + "0,0,x,0,0,0\n"),
                    Catch::Contains("path.csv:2") && Catch::Contains("column 3") && Catch::Contains("\"x\""));
  CHECK_THROWS_WITH(parse(header + "0,0,1e-3abc,0,0,0\n"), Catch::Contains("path.csv:2"));
  CHECK_THROWS_WITH(parse(header + "0,0,0,0,0,\n"),
                    Catch::Contains("path.csv:2") && Catch::Contains("column 6"));
  CHECK_THROWS_WITH(parse(header + "0,0,nan,0,0,0\n"), Catch::Contains("path.csv:2"));
  CHECK_THROWS_WITH(parse("d_xx,d_yy,d_zz\n0,0,0\n"),
                    Catch::Contains("path.csv:1") && Catch::Contains("header"));
  CHECK_THROWS_WITH(parse("0,0,0,0,0,0\n"), Catch::Contains("path.csv:1") && Catch::Contains("header"));
  CHECK_THROWS_WITH(parse(header + "# nothing\n"),
                    Catch::Contains("path.csv") && Catch::Contains("no strain"));
  CHECK_THROWS_WITH(parse(""), Catch::Contains("path.csv") && Catch::Contains("no header"));
  CHECK_THROWS_AS(read_strain_path_file("/nonexistent/path.csv"), ParameterError);
}
