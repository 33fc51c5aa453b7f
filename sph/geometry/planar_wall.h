#pragma once
/// @file
/// A wall of space: a plane polygon (a rectangle, the floor, any simple outline) holding the soil
/// on one side (docs/method/geometry-3d.md, "Planar walls").
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "sph/geometry/vec2.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

struct PlanarWall {
  Vec3 origin;                ///< the outline's first vertex
  Vec3 inward;                ///< unit normal towards the soil
  Vec3 u, v;                  ///< unit in-plane axes, u × v = inward
  std::vector<Vec2> outline;  ///< vertices in (u, v) from origin, counter-clockwise seen from the soil

  /// Signed distance of p from the plane, > 0 on the soil's side.
  double height_above(Vec3 p) const { return dot(p - origin, inward); }
  /// The plane coordinates (u, v) of p's projection on the plane.
  Vec2 in_plane(Vec3 p) const { return {dot(p - origin, u), dot(p - origin, v)}; }
  /// The point of the plane at plane coordinates q.
  Vec3 at(Vec2 q) const { return origin + q.x * u + q.y * v; }
};

/// The axis (0: x, 1: y, 2: z) the unit normal n lies along, within 10⁻¹², or −1 if none.
inline int axis_along(Vec3 n) {
  const double c[3] = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  const int axis = c[0] >= c[1] && c[0] >= c[2] ? 0 : c[1] >= c[2] ? 1 : 2;
  return c[axis] > 1.0 - 1e-12 ? axis : -1;
}

/// The wall through `points` (≥ 3 vertices of a simple polygon, counter-clockwise seen from the
/// soil: the right-hand rule makes the normal point into the soil, as a 2D wall holds the soil on
/// its left). Throws ParameterError naming `what`: fewer than 3 points, a point not finite, points
/// off one plane (by more than 10⁻⁹ of the extent), or an outline that is not a simple polygon.
PlanarWall make_planar_wall(std::span<const Vec3> points, const std::string& what);

/// The rectangle corner, corner + a, corner + a + b, corner + b; the soil on the side of a × b.
PlanarWall rectangle_wall(Vec3 corner, Vec3 a, Vec3 b, const std::string& what);

}  // namespace soilsph::sph
