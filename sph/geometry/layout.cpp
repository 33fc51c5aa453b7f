#include "sph/geometry/layout.h"

#include <algorithm>

namespace soilsph::sph {

Vec2 WallMotion::displacement(double t) const { return displacement(0.0, t); }

Vec2 WallMotion::displacement(double t, double dt) const {
  if (!moves()) return {};
  const double moving = std::max(0.0, std::min(t + dt, end) - std::max(t, start));  // overlap with [start, end]
  return moving * velocity;
}

Vec2 WallMotion::velocity_during(double t, double dt) const {
  if (!moves() || dt <= 0.0) return {};
  return (1.0 / dt) * displacement(t, dt);
}

}  // namespace soilsph::sph
