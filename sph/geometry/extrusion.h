#pragma once
/// @file
/// A plane polygon (x, y) extruded along z: the 2D regions' polygons made solids, e.g. the paper's
/// column as a slab between two planes z = z_min and z = z_max.
#include <string>
#include <vector>

#include "sph/geometry/vec2.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

struct Extrusion {
  std::vector<Vec2> outline;  ///< a simple polygon in the x–y plane, either orientation
  double z_min, z_max;

  /// Inside or on the outline (within 10⁻⁹ of its extent, as 2D regions count their outline), and
  /// z_min ≤ z ≤ z_max within the same tolerance.
  bool contains(Vec3 p) const;
  Box3 bounds() const;
};

/// The extrusion of `outline` between z_min and z_max; throws ParameterError naming `what` (e.g.
/// "scene.toml: [[regions]] 2") if the outline is not a simple polygon (geometry/polygon.h) or
/// z_max ≤ z_min or a value is not finite.
Extrusion make_extrusion(std::vector<Vec2> outline, double z_min, double z_max, const std::string& what);

}  // namespace soilsph::sph
