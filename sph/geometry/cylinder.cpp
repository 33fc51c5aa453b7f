#include "sph/geometry/cylinder.h"

namespace soilsph::sph {

bool ColumnCylinder::contains(Vec3 p) const {
  // p − base is p itself for the shorthand's base at the origin (x − 0 is exact).
  const Vec3 d = p - base;
  if (symmetry == ColumnSymmetry::Quarter && d.x < 0.0) return false;
  if (symmetry != ColumnSymmetry::None && d.z < 0.0) return false;
  const double tolerance = 1e-9 * height;
  return d.x * d.x + d.z * d.z <= radius * radius * (1.0 + 1e-9) && d.y >= -tolerance &&
         d.y <= height + tolerance;
}

Box3 ColumnCylinder::bounds() const {
  const double x_lo = symmetry == ColumnSymmetry::Quarter ? 0.0 : -radius;
  const double z_lo = symmetry == ColumnSymmetry::None ? -radius : 0.0;
  return {base + Vec3{x_lo, 0.0, z_lo}, base + Vec3{radius, height, radius}};
}

double ColumnCylinder::share() const {
  return symmetry == ColumnSymmetry::Quarter ? 0.25 : symmetry == ColumnSymmetry::Half ? 0.5 : 1.0;
}

}  // namespace soilsph::sph
