// Which scenes measure a deposit: a column always (its fixed wall and floor are the frame), a scene
// of [[regions]] only with a [deposit] table; without one its measures are NaN (null in summary.json)
// rather than numbers taken from a column's wall that the scene does not have.
#include <catch2/catch.hpp>

#include <cmath>

#include "../common/material_toml.h"
#include "helpers.h"
#include "sph/collapse.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
/// A box of soil 4 cm x 6 cm on a floor, without a wall behind it: a scene of regions.
const std::string kRegions = R"(
[scene]
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.01
gravity = 9.81

[[regions]]
shape = "box"
min = [0.0, 0.0]
max = [0.04, 0.06]

[[boundaries]]
kind = "no-slip"
points = [[-0.2, 0.0], [0.04, 0.0]]
)" + fixtures::kDruckerPragerToml;

const std::string kColumn = R"(
[scene]
column_width = 0.04
column_height = 0.06
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.01
gravity = 9.81
wall_withdrawal = "instant"
)" + fixtures::kDruckerPragerToml;

bool has_deposit_table(const Scene& scene) {
  return scene_toml(scene).find("[deposit]") != std::string::npos;
}
}  // namespace

TEST_CASE("a scene of regions without [deposit] has undefined deposit measures", "[deposit][scene]") {
  const Scene scene = test::scene_from_text(kRegions);
  CHECK_FALSE(scene.deposit.defined);
  Collapse collapse(scene);
  const DepositMetrics d = collapse.deposit();
  CHECK(std::isnan(d.runout_m));
  CHECK(std::isnan(d.height_m));
  CHECK(std::isnan(d.repose_angle_deg));
  CHECK(std::isnan(d.runout_thick_m));
  // The scene as run has no [deposit] table, so that it reads back the same.
  CHECK_FALSE(has_deposit_table(scene));
  CHECK_FALSE(parse_scene(scene_toml(scene), "as-run.toml").deposit.defined);
}

TEST_CASE("an empty [deposit] measures a scene of regions as a column from its soil's right edge",
          "[deposit][scene]") {
  const Scene scene = test::scene_from_text(kRegions + "\n[deposit]\n");
  REQUIRE(scene.deposit.defined);
  // The soil's rightmost particle centres, half a spacing inside the box's edge x = 0.04.
  CHECK(scene.deposit.origin.x == Approx(0.04 - 0.002).margin(1e-15));
  CHECK(scene.deposit.origin.y == 0.0);
  CHECK(scene.deposit.direction == Vec2{-1.0, 0.0});
  // A tenth of the soil's height between its lowest and highest particle centres: 0.06 − 0.004.
  CHECK(scene.geometry.soil_extent.height == Approx(0.056).margin(1e-15));
  CHECK(scene.deposit.toe_thickness == Approx(0.1 * 0.056));
  Collapse collapse(scene);
  // At rest before the first step: the runout is the soil's width between particle centres.
  CHECK(collapse.deposit().runout_m == Approx(0.036).margin(1e-12));
  CHECK(has_deposit_table(scene));
  CHECK(parse_scene(scene_toml(scene), "as-run.toml").deposit.origin == scene.deposit.origin);
}

TEST_CASE("a column measures its deposit without a [deposit] table", "[deposit][scene]") {
  const Scene scene = test::scene_from_text(kColumn);
  REQUIRE(scene.deposit.defined);
  CHECK(scene.deposit.origin == Vec2{0.04, 0.0});
  CHECK(has_deposit_table(scene));
  CHECK(Collapse(scene).deposit().runout_m == Approx(0.04).margin(1e-12));
}
