#include "sph/geometry/planar_wall.h"

#include <algorithm>
#include <cmath>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"

namespace soilsph::sph {

PlanarWall make_planar_wall(std::span<const Vec3> points, const std::string& what) {
  if (points.size() < 3)
    throw ParameterError(what + ": " + std::to_string(points.size()) +
                         " points (a wall's outline needs at least 3)");
  double extent = 0.0;
  for (const Vec3& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw ParameterError(what + ": a point is not finite");
    extent = std::max(extent, norm(p - points[0]));
  }
  // Newell's normal: Σ over the edges of p_i × p_{i+1}, twice the vector area, robust for any simple
  // polygon, convex or not.
  Vec3 area{};
  for (std::size_t i = 0; i < points.size(); ++i)
    area = area + cross(points[i] - points[0], points[(i + 1) % points.size()] - points[0]);
  if (norm(area) <= 1e-12 * extent * extent)
    throw ParameterError(what + ": the outline has zero area (points on one line)");
  PlanarWall w;
  w.origin = points[0];
  w.inward = (1.0 / norm(area)) * area;
  // u along the first edge that is not too short, v completing the right-handed frame.
  const Vec3 first = points[1] - points[0];
  const Vec3 along = first - dot(first, w.inward) * w.inward;
  if (norm(along) <= 1e-12 * extent) throw ParameterError(what + ": the outline repeats its first point");
  w.u = (1.0 / norm(along)) * along;
  w.v = cross(w.inward, w.u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::abs(w.height_above(points[i])) > 1e-9 * extent)
      throw ParameterError(what + ": point " + std::to_string(i + 1) + " lies " +
                           format_number(std::abs(w.height_above(points[i]))) +
                           " m off the plane of the others (a wall is plane)");
    w.outline.push_back(w.in_plane(points[i]));
  }
  if (const auto defect = polygon_defect(w.outline)) throw ParameterError(what + ": the outline " + *defect);
  return w;
}

PlanarWall rectangle_wall(Vec3 corner, Vec3 a, Vec3 b, const std::string& what) {
  const Vec3 points[4] = {corner, corner + a, corner + a + b, corner + b};
  return make_planar_wall(points, what);
}

}  // namespace soilsph::sph
