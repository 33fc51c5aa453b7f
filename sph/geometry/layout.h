#pragma once
/// @file
/// A scene's geometry as data (docs/reference/scenes.md): soil regions (boxes and polygons, each naming its
/// material) and boundaries (straight walls and polylines, each with a kind and an optional motion),
/// on one particle lattice. The column keys of [scene] build one (geometry/column.h); the
/// [[regions]] and [[boundaries]] tables build any other (geometry/read_layout.h). The lattice
/// builder, the ghost particles, the wall guard and the initial stress all read it.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sph/geometry/vec2.h"
#include "sph/geometry/wall_motion.h"

namespace soilsph::sph {

/// A soil region: filled with the lattice nodes that lie inside its outline (docs/reference/scenes.md).
struct Region {
  enum class Shape { Box, Polygon, Particles };
  Shape shape = Shape::Box;
  std::vector<Vec2> outline;  ///< counter-clockwise; a box as its four corners from (min.x, min.y);
                              ///< imported particles: the box of their cells (±Δp/2)
  std::string material;       ///< the name of its [materials.NAME] table ("" for [material])
  std::string name;           ///< for messages, e.g. "[[regions]] #1"
  std::vector<Vec2> particles;  ///< Particles: the positions read from its file (m), in the file's order
};

/// How a wall acts on the soil (stages/boundaries.h has the mirroring of each).
enum class WallKind : unsigned char { FreeSlip = 0, NoSlip = 1, Frictional = 2 };

/// Where one straight wall's ghost particles sit: rows parallel to the wall, `layers` deep behind
/// it, `count` along it: anchor + (c Δp) tangent + (k Δp) outward for c = 0 … count − 1,
/// k = 1 … layers. The anchor lies on the soil's lattice line (half a spacing in front of the wall
/// surface), at the first row along the wall.
struct GhostStrip {
  Vec2 anchor;
  Vec2 tangent;  ///< unit, the direction the rows are laid in
  Vec2 outward;  ///< unit normal pointing away from the soil (into the wall)
  int count = 0;
};

/// A boundary: a polyline wall surface with the soil on its left, walking from the first point to
/// the last.
struct Wall {
  std::vector<Vec2> points;
  WallKind kind = WallKind::FreeSlip;
  double friction_angle = 0.0;  ///< degrees, Frictional only
  WallMotion motion{};
  std::string name{};  ///< for messages, e.g. "[[boundaries]] #2"
  /// Set only where the ghosts must sit exactly as a builder computed them (the column shorthand:
  /// W + kΔp, not (W + Δp/2) − Δp/2 + kΔp, so that the column stays bit-identical); otherwise
  /// computed from the points (geometry/lattice.h).
  std::vector<GhostStrip> strips{};
  /// Its name in the run's histories (boundary_forces.csv): [[boundaries]] name, by default
  /// "boundary_K" for the K-th table; the column's are "floor", "fixed_wall" and "removable_wall".
  std::string label;
  bool symmetry_plane = false;  ///< kind = "symmetry": free slip, reported as "symmetry"
};

struct Layout {
  std::vector<Region> regions;
  std::vector<Wall> walls;
  Vec2 lattice_origin;  ///< a node of the soil lattice: nodes at origin + (i Δp, j Δp)
};

}  // namespace soilsph::sph
