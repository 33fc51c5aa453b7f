// Geometry as data: the column shorthand builds the same particles as the same column written as
// [[regions]] and [[boundaries]]; every geometry key is validated; the scene as run reads back.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "helpers.h"
#include "../common/material_toml.h"
#include "sph/geometry/polygon.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
const std::string kColumnKeys = R"(
[scene]
column_width = 0.04
column_height = 0.06
particle_spacing = 0.002
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
wall_withdrawal = "none"
floor_length = 0.25
)" + fixtures::kLinearElasticToml;

// The same column by hand: particle centres on [0, W] x [0, H], so its cells span
// [-dx/2, W + dx/2] x [-dx/2, H + dx/2] with dx = 2 mm; the walls are the cells' outer edges and
// reach H + 2h + dx/2 = 0.06 + 0.0052 + 0.001 rounded up to whole rows: 34 rows from y = 0, so
// the top at 0.067. The floor runs from W - floor_length - dx/2 = -0.211 to the fixed wall, which
// it turns into (an inner corner: the floor's rows fill the corner block).
const std::string kColumnAsLayout = R"(
[scene]
particle_spacing = 0.002
smoothing_ratio = 1.3
end_time = 0.1
gravity = [0.0, -9.81]
lattice_origin = [0.0, 0.0]
[materials.sand]
model = "linear-elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
[[regions]]
shape = "box"
min = [-0.001, -0.001]
max = [0.041, 0.061]
material = "sand"
[[boundaries]]
kind = "no-slip"
points = [[-0.211, -0.001], [0.041, -0.001]]
[[boundaries]]
kind = "free-slip"
points = [[0.041, -0.001], [0.041, 0.067]]
[[boundaries]]
kind = "free-slip"
points = [[-0.001, 0.067], [-0.001, -0.001]]
)";

using Key = std::tuple<long long, long long, int, long long, long long>;
/// Ghosts as sortable keys: position in units of 1e-9 m, kind, inward normal.
std::vector<Key> ghost_keys(const Particles& p) {
  std::vector<Key> keys;
  for (std::size_t g = 0; g < p.boundary_count(); ++g) {
    const std::size_t b = p.soil_count + g;
    keys.emplace_back(std::llround(p.x[b] * 1e9), std::llround(p.y[b] * 1e9), static_cast<int>(p.boundary_kind[g]),
                      std::llround(p.wall_nx[g]), std::llround(p.wall_ny[g]));
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}
}  // namespace

TEST_CASE("the column keys build the same particles as the column written as regions and boundaries",
          "[geometry]") {
  const Scene shorthand = test::scene_from_text(kColumnKeys);
  const Scene layout = test::scene_from_text(kColumnAsLayout);
  const Particles a = build_particles(shorthand), b = build_particles(layout);
  // Soil: 21 x 31 lattice points, the same positions in the same order.
  REQUIRE(a.soil_count == 21 * 31);
  REQUIRE(b.soil_count == a.soil_count);
  for (std::size_t i = 0; i < a.soil_count; ++i) {
    CHECK(b.x[i] == Approx(a.x[i]).margin(1e-12));
    CHECK(b.y[i] == Approx(a.y[i]).margin(1e-12));
    CHECK(b.layer[i] == a.layer[i]);
  }
  // Ghosts: 3 layers x (floor 0.25/0.002 + 1 + 3 corner columns = 129, two walls of 34 rows).
  REQUIRE(a.boundary_count() == 3 * (129 + 34 + 34));
  CHECK(ghost_keys(a) == ghost_keys(b));
  // The same geostatic surface and the same stress.
  Particles sa = a, sb = b;
  set_geostatic_state(sa, shorthand);
  set_geostatic_state(sb, layout);
  for (std::size_t i = 0; i < a.soil_count; ++i) CHECK(sb.syy[i] == Approx(sa.syy[i]).margin(1e-9));
  // With the left wall withdrawn, the third boundary is absent in both.
  const Scene instant = test::scene_from_text(kColumnKeys, {"scene.wall_withdrawal=\"instant\""});
  CHECK(build_particles(instant).boundary_count() == 3 * (129 + 34));
}

TEST_CASE("the shorthand places every particle exactly where the column always had it", "[geometry]") {
  // The former builder's formulas, operation for operation: soil (c dx, r dx); floor ghosts
  // (W + layers dx - c dx, -k dx) from under the fixed wall leftwards; fixed wall (W + k dx, r dx).
  const Scene s = test::scene_from_text(kColumnKeys, {"scene.wall_withdrawal=\"instant\""});
  const Particles p = build_particles(s);
  const double W = 0.04, dx = 0.002;
  const int layers = 3, nx = 21, ny = 31, floor_columns = 125 + 1 + layers, rows = 34;
  std::size_t i = 0;
  bool exact = true;
  for (int r = 0; r < ny; ++r)
    for (int c = 0; c < nx; ++c, ++i) exact = exact && p.x[i] == c * dx && p.y[i] == r * dx;
  for (int k = 1; k <= layers; ++k)
    for (int c = 0; c < floor_columns; ++c, ++i) exact = exact && p.x[i] == W + layers * dx - c * dx && p.y[i] == -k * dx;
  for (int k = 1; k <= layers; ++k)
    for (int r = 0; r < rows; ++r, ++i) exact = exact && p.x[i] == W + k * dx && p.y[i] == r * dx;
  CHECK(i == p.size());
  CHECK(exact);
}

TEST_CASE("the scene as run reads back to the same layout", "[geometry][record]") {
  const Scene s = test::scene_from_text(kColumnAsLayout);
  const Scene again = parse_scene(scene_toml(s), "again.toml");
  CHECK(scene_toml(again) == scene_toml(s));
  CHECK(ghost_keys(build_particles(again)) == ghost_keys(build_particles(s)));
  CHECK(again.geometry.gravity == Vec2{0.0, -9.81});
}

TEST_CASE("geometry keys are validated with the file, the table and the key named", "[geometry]") {
  const auto with = [](const std::string& replace, const std::string& by) {
    std::string text = kColumnAsLayout;
    const std::size_t at = text.find(replace);
    REQUIRE(at != std::string::npos);
    return test::scene_from_text(text.replace(at, replace.size(), by));
  };
  CHECK_THROWS_WITH(with("max = [0.041, 0.061]", "max = [0.0415, 0.061]"),
                    Contains("[regions #1] max x = 0.0415 m does not fall on a cell edge") &&
                        Contains("the nearest are 0.041 and 0.043") &&
                        Contains("[scene] particle_spacing = 0.002"));
  CHECK_THROWS_WITH(with("shape = \"box\"\nmin = [-0.001, -0.001]\nmax = [0.041, 0.061]",
                         "shape = \"polygon\"\npoints = [[0, 0], [0.04, 0.06], [0.04, 0], [0, 0.06]]"),
                    Contains("[regions #1] points: the polygon is not simple"));
  CHECK_THROWS_WITH(with("shape = \"box\"\nmin = [-0.001, -0.001]\nmax = [0.041, 0.061]",
                         "shape = \"polygon\"\npoints = [[0, 0], [0.02, 0.02], [0.04, 0.04]]"),
                    Contains("[regions #1] points: the polygon folds back on itself"));
  CHECK_THROWS_WITH(build_particles(with("shape = \"box\"\nmin = [-0.001, -0.001]\nmax = [0.041, 0.061]",
                         "shape = \"polygon\"\npoints = [[0.0001, 0.0001], [0.0009, 0.0001], [0.0005, 0.0009]]")),
                    Contains("[regions #1] holds no particle of the lattice"));
  CHECK_THROWS_WITH(with("material = \"sand\"", "material = \"clay\""),
                    Contains("[regions #1] material") && Contains("\"sand\""));
  CHECK_THROWS_WITH(with("kind = \"no-slip\"", "kind = \"frictional\""),
                    Contains("[boundaries #1] wall_friction_angle: is missing"));
  CHECK_THROWS_WITH(with("kind = \"no-slip\"", "kind = \"sticky\""),
                    Contains("[boundaries #1] kind") && Contains("\"free-slip\", \"no-slip\", \"frictional\""));
  CHECK_THROWS_WITH(with("kind = \"no-slip\"", "kind = \"no-slip\"\nend = 1.0"),
                    Contains("[boundaries #1] end: needs velocity"));
  CHECK_THROWS_WITH(with("kind = \"no-slip\"", "kind = \"no-slip\"\nvelocity = [0, 1]\nstart = 0.5\nend = 0.2"),
                    Contains("[boundaries #1] end = 0.2 is out of range"));
  CHECK_THROWS_WITH(with("kind = \"no-slip\"", "kind = \"no-slip\"\nheight = 1"),
                    Contains("[boundaries #1] height: is not a known key"));
  CHECK_THROWS_WITH(with("points = [[-0.211, -0.001], [0.041, -0.001]]", "points = [[-0.211, -0.001]]"),
                    Contains("[boundaries #1] points must be (an array of at least 2"));
  CHECK_THROWS_WITH(with("gravity = [0.0, -9.81]", "gravity = [0.0, -9.81, 1.0]"),
                    Contains("[scene] gravity must be [x, y]"));
  CHECK_THROWS_WITH(with("lattice_origin = [0.0, 0.0]", "column_width = 0.04"),
                    Contains("[scene] column_width: and [[regions]] exclude each other"));
  // A second material in one scene: each region keeps its own (tests/sph/test_materials.cpp).
  std::string two = kColumnAsLayout + R"(
[materials.clay]
model = "linear-elastic"
density = 1800.0
young_modulus = 1.0e6
poisson_ratio = 0.3
[[regions]]
shape = "box"
min = [-0.001, 0.061]
max = [0.041, 0.081]
material = "clay"
)";
  const Scene both = test::scene_from_text(two);
  CHECK(both.material_names == std::vector<std::string>{"sand", "clay"});
  CHECK(both.region_material == std::vector<int>{0, 1});
}

TEST_CASE("polygons: simple, oriented, and filled with the nodes inside", "[geometry]") {
  const std::vector<Vec2> triangle{{0, 0}, {1, 0}, {0, 1}};
  CHECK(signed_area(triangle) == Approx(0.5));
  CHECK(!polygon_defect(triangle));
  CHECK(inside_or_on(triangle, {0.2, 0.2}, 1e-12));
  CHECK(inside_or_on(triangle, {0.5, 0.5}, 1e-12));  // on the hypotenuse
  CHECK(!inside_or_on(triangle, {0.6, 0.6}, 1e-12));
  // A right triangle of legs 20 spacings on the lattice of cell centres: the nodes (i + 1/2, j + 1/2)
  // with i + j + 1 <= 20 (the 20 on the hypotenuse count as inside): 20·21/2 = 210.
  const Scene s = test::scene_from_text(R"(
[scene]
particle_spacing = 0.001
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
[material]
model = "linear-elastic"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
[[regions]]
shape = "polygon"
points = [[0.0, 0.0], [0.02, 0.0], [0.0, 0.02]]
)");
  CHECK(build_particles(s).soil_count == 210);
  CHECK(build_particles(s).boundary_count() == 0);
}

TEST_CASE("wall_withdrawal = \"lift\" makes the left wall a gate rising at lift_speed until it clears the column",
          "[geometry]") {
  const Scene s = test::shipped_scene("gate-lift", {"scene.particle_spacing=0.004"});
  const Wall& gate = s.geometry.layout.walls.at(2);
  // The column's top + 2h + the spacing above the gate's lower end at -dx/2, at 1 m/s.
  const double clear = (0.06 + 2.0 * 1.3 * 0.004 + 0.004 + 0.002) / 1.0;
  CHECK(gate.motion.velocity == Vec2{0.0, 1.0});
  CHECK(gate.motion.start == 0.0);
  CHECK(gate.motion.end == Approx(clear));
  CHECK(gate.motion.removed_at == Approx(clear));
  // Its ghosts exist from t = 0 (unlike "instant"): 3 layers of the walls' 19 rows more.
  const Scene instant = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004"});
  CHECK(build_particles(s).boundary_count() == build_particles(instant).boundary_count() + 3 * 19);
  CHECK_THROWS_WITH(test::shipped_scene("gate-lift", {"scene.wall_withdrawal=\"none\""}),
                    Contains("[scene] lift_speed: needs wall_withdrawal = \"lift\""));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.wall_withdrawal=\"lift\""}),
                    Contains("[scene] lift_speed: is missing"));
}
