// The cut planes of half and quarter cylinders (sph/cylinder_cuts.h): each must be closed by a
// symmetry or free-slip wall that stays, faces the soil, lies in the plane within half a spacing and
// covers the cut face, or `soilsph check` warns of it; the shipped column's own planes close its cuts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "sph/cylinder_cuts.h"
#include "sph/scene_3d.h"

using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {

const std::string kColumn = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";

/// A cylinder r = 4 cm, H = 2 cm about the axis x = 0.08, z = −0.04 (cell edges at Δp = 4 mm) of
/// `part`, on the floor y = 0, with the [[boundaries]] `walls`.
std::vector<std::string> cuts_of(const std::string& part, const std::string& walls = "") {
  return open_cylinder_cuts(parse_scene_3d(R"(
[scene]
dimension = 3
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.5
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 5.0e6
poisson_ratio = 0.3
[[regions]]
shape = "cylinder"
base_centre = [0.08, 0.0, -0.04]
radius = 0.04
height = 0.02
part = ")" + part + "\"\n" + walls,
                                           "cuts.toml")
                                .geometry);
}

/// A rectangle wall named `name` of `kind`, from `corner` along `a` then `b` (the soil on a × b's side).
std::string plane(const std::string& name, const std::string& kind, const std::string& corner,
                  const std::string& a, const std::string& b, const std::string& extra = "") {
  return "[[boundaries]]\nshape = \"rectangle\"\nname = \"" + name + "\"\nkind = \"" + kind + "\"\ncorner = " +
         corner + "\nedges = [" + a + ", " + b + "]\n" + extra;
}

const std::string kUp = "[0.0, 0.03, 0.0]";
/// The quarter's planes x = 0.08 (soil on +x: y × z) and z = −0.04 (soil on +z: x × y), each 5 cm
/// across from the axis and 3 cm high.
std::string x_plane(const std::string& kind, const std::string& extra = "") {
  return plane("mirror_x", kind, "[0.08, 0.0, -0.04]", kUp, "[0.0, 0.0, 0.05]", extra);
}
std::string z_plane(const std::string& kind, const std::string& corner = "[0.08, 0.0, -0.04]",
                    const std::string& across = "[0.05, 0.0, 0.0]", const std::string& extra = "") {
  return plane("mirror_z", kind, corner, across, kUp, extra);
}

}  // namespace

TEST_CASE("a quarter or half cylinder without its mirrors has each open cut named", "[regions3d][cuts]") {
  const std::vector<std::string> quarter = cuts_of("quarter");
  REQUIRE(quarter.size() == 2);
  CHECK_THAT(quarter[0], Contains("[regions #1], a quarter cylinder") && Contains("cut plane x = 0.08 m") &&
                             Contains("z from -0.04 to 0") && Contains("flow out") &&
                             Contains("kind = \"symmetry\""));
  CHECK_THAT(quarter[1], Contains("cut plane z = -0.04 m") && Contains("x from 0.08 to 0.12 m"));
  const std::vector<std::string> half = cuts_of("half");
  REQUIRE(half.size() == 1);
  CHECK_THAT(half[0], Contains("a half cylinder") && Contains("cut plane z = -0.04 m") &&
                          Contains("x from 0.04 to 0.12 m") && Contains("y from 0 to 0.02 m"));
  CHECK(cuts_of("whole").empty());
  // One plane closes one cut of the quarter, not the other.
  const std::vector<std::string> one = cuts_of("quarter", x_plane("symmetry"));
  REQUIRE(one.size() == 1);
  CHECK_THAT(one[0], Contains("cut plane z = -0.04 m"));
}

TEST_CASE("symmetry or free-slip walls that stay in the cut planes close them", "[regions3d][cuts]") {
  CHECK(cuts_of("quarter", x_plane("symmetry") + z_plane("symmetry")).empty());
  CHECK(cuts_of("quarter", x_plane("free-slip") + z_plane("symmetry")).empty());
  // Half a spacing behind the cut (a cut through lattice nodes is mirrored there) still closes it.
  CHECK(cuts_of("quarter", x_plane("symmetry") + z_plane("symmetry", "[0.08, 0.0, -0.042]")).empty());
  CHECK(cuts_of("half", z_plane("symmetry", "[0.04, 0.0, -0.04]", "[0.09, 0.0, 0.0]")).empty());
  // The shipped column's symmetry planes close its quarter's and its half's cuts.
  for (const std::string symmetry : {"quarter", "half", "none"}) {
    INFO(symmetry);
    CHECK(open_cylinder_cuts(load_scene_3d(kColumn, std::vector<std::string>{"scene.symmetry=\"" + symmetry + "\""}).geometry).empty());
  }
}

TEST_CASE("a wall in a cut plane that is no mirror, moves, goes, stands off or falls short leaves it open",
          "[regions3d][cuts]") {
  const std::string x = x_plane("symmetry");
  const auto only_cut = [](const std::vector<std::string>& cuts) {
    REQUIRE(cuts.size() == 1);
    return cuts.front();
  };
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("no-slip"))),
             Contains("z = -0.04 m") && Contains("\"mirror_z\"") && Contains("no-slip") && Contains("no mirror"));
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("frictional", "[0.08, 0.0, -0.04]", "[0.05, 0.0, 0.0]",
                                                     "wall_friction_angle = 20.0\n"))),
             Contains("frictional"));
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("free-slip", "[0.08, 0.0, -0.04]", "[0.05, 0.0, 0.0]",
                                                     "removed_at = 0.1\n"))),
             Contains("\"mirror_z\"") && Contains("removed"));
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("free-slip", "[0.08, 0.0, -0.04]", "[0.05, 0.0, 0.0]",
                                                     "velocity = [1.0, 0.0, 0.0]\nend = 0.1\n"))),
             Contains("moves"));
  // A spacing behind the cut is no longer in it; 3 cm of the quarter's 4 cm face fall short; so does
  // the quarter's width under a half.
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("symmetry", "[0.08, 0.0, -0.044]"))), Contains("z = -0.04 m"));
  CHECK_THAT(only_cut(cuts_of("quarter", x + z_plane("symmetry", "[0.08, 0.0, -0.04]", "[0.03, 0.0, 0.0]"))),
             Contains("does not cover"));
  CHECK_THAT(only_cut(cuts_of("half", z_plane("symmetry"))), Contains("does not cover"));
  // A wall in the plane facing away from the soil is no mirror of it.
  CHECK(cuts_of("quarter", x + plane("back", "symmetry", "[0.08, 0.0, -0.04]", kUp, "[0.05, 0.0, 0.0]")).size() == 1);
}

TEST_CASE("the quarter cylinder of docs/reference/scenes.md: its two symmetry planes close both cuts",
          "[regions3d][cuts]") {
  const std::string quarter = R"(
[scene]
dimension = 3
particle_spacing = 0.005
smoothing_ratio = 1.3
end_time = 0.5
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 5.0e6
poisson_ratio = 0.3
[[regions]]
shape = "cylinder"
base_centre = [0.0, 0.0, 0.0]
radius = 0.05
height = 0.1
part = "quarter"
)";
  const std::string mirrors = R"(
[[boundaries]]
shape = "rectangle"
name = "symmetry_yz"
kind = "symmetry"
corner = [0.0, 0.0, 0.0]
edges = [[0.0, 0.15, 0.0], [0.0, 0.0, 0.35]]
[[boundaries]]
shape = "rectangle"
name = "symmetry_xy"
kind = "symmetry"
corner = [0.0, 0.0, 0.0]
edges = [[0.35, 0.0, 0.0], [0.0, 0.15, 0.0]]
)";
  const Scene3 scene = parse_scene_3d(quarter + mirrors, "docs.toml");
  CHECK(open_cylinder_cuts(scene.geometry).empty());
  CHECK(open_cylinder_cuts(parse_scene_3d(quarter, "docs.toml").geometry).size() == 2);
  // The mirrors run the floor's length: its far edges lie within them.
  const PlanarWall& floor = scene.geometry.walls.front().plane;
  double far_x = 0.0, far_z = 0.0;
  for (const Vec2& q : floor.outline) far_x = std::max(far_x, floor.at(q).x), far_z = std::max(far_z, floor.at(q).z);
  CHECK(far_x < 0.35);
  CHECK(far_z < 0.35);
  CHECK(far_x > 0.3);
}
