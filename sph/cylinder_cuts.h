#pragma once
/// @file
/// The cut planes of a 3D scene's half and quarter cylinders: a cut part of a cylinder is one of a
/// symmetric problem, run in part only when a mirror (a symmetry or free-slip wall) closes each of
/// its cut planes; otherwise the soil flows out through the cut. `soilsph check` warns of each cut
/// left open (docs/reference/scenes.md, "Regions in 3D").
#include <string>
#include <vector>

#include "sph/scene_3d.h"

namespace soilsph::sph {

/// Each cut plane of a half or quarter cylinder among `g.regions` that no wall of `g.walls` closes,
/// as a sentence naming the region, the plane and its face (e.g. "[regions #1], a half cylinder,
/// has no symmetry or free-slip wall in its cut plane z = 0 m ..."). A wall closes a cut when it is
/// free-slip (kind "free-slip" or "symmetry"), stays (neither moves nor goes), faces the soil across
/// the cut (its inward normal along the cut's), lies in the cut plane within half a particle
/// spacing (the cut may pass through lattice nodes, its mirror half a spacing behind them) and covers
/// the cut face (x or z from the axis to the rim, y over the height) within half a spacing. Empty
/// when every cut is closed, and for whole cylinders.
std::vector<std::string> open_cylinder_cuts(const Geometry3& g);

}  // namespace soilsph::sph
