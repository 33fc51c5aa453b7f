#pragma once
/// @file
/// Ghost particles behind planar walls, on the soil's lattice: `layers` deep behind each wall, the
/// edges and corners where walls meet filled once (docs/method/geometry-3d.md, "Ghosts").
#include <span>
#include <vector>

#include "sph/geometry/planar_wall.h"
#include "sph/geometry/solid.h"

namespace soilsph::sph {

struct GhostPoint3 {
  Vec3 position;
  Vec3 inward;  ///< the unit normal of its wall, towards the soil
  int wall;     ///< index into the walls
};

/// The outline of `walls[w]` grown in its plane by `reach` across each edge where another wall
/// meets it at an inner corner, i.e. where the edge lies in the other wall (both ends on its plane
/// and outline, within 10⁻⁹ of the extent) and the other wall holds the soil back towards this
/// one (its inward normal against the edge's outward direction in this plane): the floor under a
/// side wall. Edges that are free, or meet a wall at an outer corner (a step down), stay: growing
/// them would put ghosts into the soil beyond. Each vertex of the grown outline is where the lines
/// of its two (moved or kept) edges cross.
std::vector<Vec2> grown_outline(std::span<const PlanarWall> walls, std::size_t w, double reach);

/// Every lattice node behind a wall by more than 0 and at most layers·Δp (within 10⁻⁹ Δp), whose
/// projection on the wall's plane lies in its outline grown by layers·Δp at inner corners
/// (grown_outline), wall by wall, each in k, j, i order. A node behind two or three walls (an edge
/// or a corner block) is kept once, for the first wall that claims it, so no two ghosts coincide;
/// at an outer corner the two walls' ghost slabs overlap in the wedge behind it and cover it.
/// Walls marked in `mirrored` (symmetry planes, whose ghosts are the soil's mirror images,
/// stages/mirror_images.h) get none, but still grow the outlines of the walls they meet, so that
/// the floor's ghosts reach on under a symmetry plane; none marked if it is empty.
std::vector<GhostPoint3> planar_ghost_points(std::span<const PlanarWall> walls, const Lattice3& lattice,
                                             int layers, const std::vector<bool>& mirrored = {});

}  // namespace soilsph::sph
