#include "sph/geometry/column.h"

#include <cmath>

namespace soilsph::sph {

namespace {
int lattice_count(double length, double spacing) { return static_cast<int>(std::lround(length / spacing)) + 1; }
}  // namespace

Layout column_layout(const ColumnKeys& c, const std::string& material) {
  const double dx = c.spacing, half = 0.5 * dx, W = c.width;
  const double top = c.height + 2.0 * c.smoothing_length;  // the walls' last ghost row
  const int rows = lattice_count(top, dx);
  Layout layout;
  layout.lattice_origin = {0.0, 0.0};
  layout.regions.push_back({Region::Shape::Box,
                            {{-half, -half}, {W + half, -half}, {W + half, c.height + half}, {-half, c.height + half}},
                            material,
                            "[scene] column",
                            {}});
  // The strips are given, not derived from the surfaces, so that each ghost is computed by the same
  // operations in the same order as the shipped column runs were validated with (bit-identical
  // frames, tests/sph/test_geometry.cpp): the floor's rows from under the
  // fixed wall's last layer (x = W + layers Δp) leftwards, the walls' rows upwards from y = 0.
  Wall floor{{{W - c.floor_length - half, -half}, {W + half, -half}}, WallKind::NoSlip, 0.0, {}, "[scene] floor", {}, "floor"};
  floor.strips = {{{W + c.layers * dx, 0.0}, {-1.0, 0.0}, {0.0, -1.0}, lattice_count(c.floor_length, dx) + c.layers}};
  Wall fixed{{{W + half, -half}, {W + half, top + half}}, WallKind::FreeSlip, 0.0, {}, "[scene] fixed wall", {}, "fixed_wall"};
  fixed.strips = {{{W, 0.0}, {0.0, 1.0}, {1.0, 0.0}, rows}};
  Wall removable{{{-half, top + half}, {-half, -half}}, WallKind::FreeSlip, 0.0, {}, "[scene] removable wall", {}, "removable_wall"};
  removable.strips = {{{0.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, rows}};
  if (c.left_wall_withdrawn) removable.motion.removed_at = 0.0;
  if (c.lift_speed > 0.0) {
    const double clear = (top + dx + half) / c.lift_speed;  // its lower end from −Δp/2 to H + 2h + Δp
    removable.motion = {clear, {0.0, c.lift_speed}, 0.0, clear};
  }
  layout.walls = {floor, fixed, removable};
  return layout;
}

}  // namespace soilsph::sph
