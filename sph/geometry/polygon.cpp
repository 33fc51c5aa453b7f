#include "sph/geometry/polygon.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace soilsph::sph {

double signed_area(std::span<const Vec2> polygon) {
  double twice = 0.0;
  for (std::size_t i = 0, n = polygon.size(); i < n; ++i) twice += cross(polygon[i], polygon[(i + 1) % n]);
  return 0.5 * twice;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double length2 = dot(ab, ab);
  const double s = length2 > 0.0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return norm(p - (a + s * ab));
}

namespace {
/// Segments [a, b] and [c, d] share a point (touching counts).
bool segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double scale = std::max({norm(b - a), norm(d - c), 1e-300});
  const double eps = 1e-12 * scale;
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > eps && d2 < -eps) || (d1 < -eps && d2 > eps)) && ((d3 > eps && d4 < -eps) || (d3 < -eps && d4 > eps)))
    return true;  // proper crossing
  // touching or collinear overlap: an end point on the other segment
  return distance_to_segment(c, a, b) <= eps || distance_to_segment(d, a, b) <= eps ||
         distance_to_segment(a, c, d) <= eps || distance_to_segment(b, c, d) <= eps;
}
}  // namespace

std::optional<std::string> polygon_defect(std::span<const Vec2> polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return "has " + std::to_string(n) + " vertices (a polygon needs at least 3)";
  double extent = 0.0;
  for (const Vec2& v : polygon) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
  for (std::size_t i = 0; i < n; ++i)
    if (norm(polygon[(i + 1) % n] - polygon[i]) <= 1e-12 * extent)
      return "repeats vertex " + std::to_string(i + 1) + " (an edge of zero length)";
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) {
        // Adjacent edges share one vertex; they must not fold back onto each other.
        const Vec2 a = polygon[i], b = polygon[(i + 1) % n], c = polygon[j], d = polygon[(j + 1) % n];
        const Vec2 u = b - a, v = d - c;
        if (std::abs(cross(u, v)) <= 1e-12 * norm(u) * norm(v) && dot(u, v) < 0.0)
          return "folds back on itself at a vertex (edges " + std::to_string(i + 1) + " and " + std::to_string(j + 1) + ")";
        continue;
      }
      if (segments_meet(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) {
        std::ostringstream msg;
        msg << "is not simple: edge " << i + 1 << " meets edge " << j + 1;
        return msg.str();
      }
    }
  if (std::abs(signed_area(polygon)) <= 1e-12 * extent * extent) return "has zero area";
  return std::nullopt;
}

bool inside_or_on(std::span<const Vec2> polygon, Vec2 p, double tolerance) {
  bool inside = false;
  for (std::size_t i = 0, n = polygon.size(), j = n - 1; i < n; j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if (distance_to_segment(p, a, b) <= tolerance) return true;
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
  }
  return inside;
}

}  // namespace soilsph::sph
