#include "sph/geometry/surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace soilsph::sph {

double surface_height_above(std::span<const Region> regions, Vec2 down, Vec2 p) {
  // Along the surface: s = a horizontal coordinate (the vertical through p is s = s_p);
  // height = −down · x, as Geometry::height.
  const Vec2 across{-down.y, down.x};
  const auto height = [&](Vec2 v) { return -(down.x * v.x + down.y * v.y); };
  const double sp = dot(across, p);
  double top = -std::numeric_limits<double>::infinity();
  for (const Region& r : regions) {
    const std::size_t n = r.outline.size();
    double extent = 0.0;
    for (const Vec2& v : r.outline) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
    const double tolerance = 1e-12 * std::max(extent, 1e-300);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 a = r.outline[k], b = r.outline[(k + 1) % n];
      const double sa = dot(across, a) - sp, sb = dot(across, b) - sp;
      const double ha = height(a), hb = height(b);
      if (std::abs(sa - sb) <= tolerance) {  // an edge along the vertical
        if (std::abs(sa) <= tolerance) top = std::max({top, ha, hb});
        continue;
      }
      if ((sa > tolerance && sb > tolerance) || (sa < -tolerance && sb < -tolerance)) continue;
      // ha == hb (a level edge) gives ha exactly: ha + t·0.
      const double t = std::clamp(sa / (sa - sb), 0.0, 1.0);
      top = std::max(top, ha + t * (hb - ha));
    }
  }
  return top;
}

}  // namespace soilsph::sph
