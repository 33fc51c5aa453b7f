#include "sph/cylinder_cuts.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"

namespace soilsph::sph {

namespace {

/// A cut plane of a cylinder part and the rectangle of it the soil stands on: the points
/// corner + s·along + t·up for 0 ≤ s ≤ width, 0 ≤ t ≤ height.
struct CutFace {
  char axis;     ///< 'x' (the plane x = x_c) or 'z' (z = z_c)
  Vec3 inward;   ///< the soil's side, +x or +z
  Vec3 corner;   ///< on the axis's foot side of the face, at the base
  Vec3 along;    ///< unit, across the face (x or z)
  double width;  ///< m
  double height;  ///< m
};

std::vector<CutFace> cut_faces(const ColumnCylinder& c) {
  const double r = c.radius, H = c.height;
  const Vec3 x{1.0, 0.0, 0.0}, z{0.0, 0.0, 1.0};
  switch (c.symmetry) {
    case ColumnSymmetry::Half:  // z ≥ z_c: the plane z = z_c across the whole diameter
      return {{'z', z, c.base - r * x, x, 2.0 * r, H}};
    case ColumnSymmetry::Quarter:  // x ≥ x_c and z ≥ z_c: each plane from the axis to the rim
      return {{'x', x, c.base, z, r, H}, {'z', z, c.base, x, r, H}};
    case ColumnSymmetry::None: return {};
  }
  return {};
}

/// Whether `wall`'s outline holds the face, sampled at most a spacing apart, within `tolerance`.
bool covers(const PlanarWall& wall, const CutFace& face, double spacing, double tolerance) {
  const Vec3 up{0.0, 1.0, 0.0};
  const int across = std::max(1, static_cast<int>(std::ceil(face.width / spacing)));
  const int high = std::max(1, static_cast<int>(std::ceil(face.height / spacing)));
  for (int i = 0; i <= across; ++i)
    for (int j = 0; j <= high; ++j) {
      const Vec3 p = face.corner + (face.width * i / across) * face.along + (face.height * j / high) * up;
      if (!inside_or_on(wall.outline, wall.in_plane(p), tolerance)) return false;
    }
  return true;
}

std::string kind_name(WallKind kind) {
  return kind == WallKind::FreeSlip ? "free-slip" : kind == WallKind::NoSlip ? "no-slip" : "frictional";
}

/// Nothing if a wall closes the face; otherwise why not, in words ("" when no wall lies in its plane).
std::optional<std::string> why_open(const CutFace& face, const std::vector<Wall3>& walls, double spacing) {
  const double near = 0.5 * spacing * (1.0 + 1e-6);
  std::string why;
  for (const Wall3& wall : walls) {
    const PlanarWall& plane = wall.plane;
    if (dot(plane.inward, face.inward) < 1.0 - 1e-9 || std::abs(plane.height_above(face.corner)) > near) continue;
    const std::string name = "the wall \"" + wall.label + "\" in it ";
    if (!covers(plane, face, spacing, near))
      why = name + "does not cover the cut face";
    else if (wall.kind != WallKind::FreeSlip)
      why = name + "is " + kind_name(wall.kind) + ": it holds the soil but is no mirror";
    else if (wall.motion.changes())
      why = name + (wall.motion.moves() ? "moves" : "is removed during the run");
    else
      return std::nullopt;
  }
  return why;
}

std::string part_name(ColumnSymmetry s) { return s == ColumnSymmetry::Half ? "a half cylinder" : "a quarter cylinder"; }

}  // namespace

std::vector<std::string> open_cylinder_cuts(const Geometry3& g) {
  std::vector<std::string> open;
  for (const SoilRegion3& region : g.regions) {
    const auto* cylinder = std::get_if<ColumnCylinder>(&region.shape);
    if (!cylinder) continue;
    for (const CutFace& face : cut_faces(*cylinder)) {
      const std::optional<std::string> why = why_open(face, g.walls, g.particle_spacing);
      if (!why) continue;
      const char across = face.axis == 'x' ? 'z' : 'x';
      const double at = face.axis == 'x' ? face.corner.x : face.corner.z;
      const double from = across == 'x' ? face.corner.x : face.corner.z;
      open.push_back(region.name + ", " + part_name(cylinder->symmetry) +
                     ", has no symmetry or free-slip wall in its cut plane " + face.axis + " = " +
                     format_number(at) + " m (" + across + " from " + format_number(from) + " to " +
                     format_number(from + face.width) + " m, y from " + format_number(face.corner.y) + " to " +
                     format_number(face.corner.y + face.height) + " m)" + (why->empty() ? "" : "; " + *why) +
                     ": the soil would flow out through the cut. Close it with a [[boundaries]] rectangle of "
                     "kind = \"symmetry\" in that plane, or take part = \"whole\"");
    }
  }
  return open;
}

}  // namespace soilsph::sph
