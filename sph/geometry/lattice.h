#pragma once
/// @file
/// Particles from a layout: the soil lattice fitted into the regions and the ghost rows behind the
/// walls (docs/reference/scenes.md).
#include <string>
#include <vector>

#include "sph/geometry/layout.h"

namespace soilsph::sph {

struct SoilNode {
  Vec2 position;
  int region;  ///< index into Layout::regions
};

/// The lattice nodes origin + (i Δp, j Δp) inside each region (on its outline within 10⁻⁹ Δp
/// counts as inside), region by region, each row by row from its lowest (j, then i); a node that an
/// earlier region holds is not repeated. Throws ParameterError naming a region that holds none.
std::vector<SoilNode> soil_nodes(const Layout& layout, double spacing, const std::string& source);

/// The ghost rows of each straight piece of a wall: given (Wall::strips) or from its points: rows
/// parallel to the piece, the first half a spacing along it from its start, max(1, round(L/Δp))
/// of them; where the polyline turns towards the soil (an inner corner, e.g. floor then wall) the
/// piece before the corner runs on `layers` rows past it and fills the corner block. A wall whose
/// last point is another wall's first point turns into it there (a floor and a wall of two kinds).
/// A symmetry line has no ghosts of its own (the soil's mirror images stand behind it), so a wall
/// that turns from one towards the soil starts `layers` rows before its first point instead.
std::vector<GhostStrip> strips_of(const Layout& layout, const Wall& wall, double spacing, int layers);

struct GhostPoint {
  Vec2 position;
  Vec2 inward;  ///< unit wall normal towards the soil
  int wall;     ///< index into Layout::walls
};

/// Every ghost particle of the walls present at t = 0 (not removed_at = 0) other than the symmetry
/// lines (stages/mirror_images.h), wall by wall, strip by
/// strip, layer by layer. Where the polyline turns away from the soil (an outer corner) a piece's
/// ghosts that fall in the previous piece's rows are left out, so no two ghosts coincide.
std::vector<GhostPoint> ghost_points(const Layout& layout, double spacing, int layers);

}  // namespace soilsph::sph
