#include "sph/geometry/extrusion.h"

#include <algorithm>
#include <cmath>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"

namespace soilsph::sph {

namespace {
double extent_of(const Extrusion& e) {
  double extent = std::max(std::abs(e.z_min), std::abs(e.z_max));
  for (const Vec2& v : e.outline) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
  return std::max(extent, 1e-300);
}
}  // namespace

bool Extrusion::contains(Vec3 p) const {
  const double tolerance = 1e-9 * extent_of(*this);
  return p.z >= z_min - tolerance && p.z <= z_max + tolerance && inside_or_on(outline, {p.x, p.y}, tolerance);
}

Box3 Extrusion::bounds() const {
  Box3 b{{outline.front().x, outline.front().y, z_min}, {outline.front().x, outline.front().y, z_max}};
  for (const Vec2& v : outline) b = merged(b, Box3{{v.x, v.y, z_min}, {v.x, v.y, z_max}});
  return b;
}

Extrusion make_extrusion(std::vector<Vec2> outline, double z_min, double z_max, const std::string& what) {
  for (const Vec2& v : outline)
    if (!std::isfinite(v.x) || !std::isfinite(v.y))
      throw ParameterError(what + ": the outline has a vertex that is not finite");
  if (const auto defect = polygon_defect(outline)) throw ParameterError(what + ": the outline " + *defect);
  if (!std::isfinite(z_min) || !std::isfinite(z_max) || !(z_max > z_min))
    throw ParameterError(what + ": z_max = " + format_number(z_max) +
                         " m must be finite and above z_min = " + format_number(z_min) + " m");
  return {std::move(outline), z_min, z_max};
}

}  // namespace soilsph::sph
