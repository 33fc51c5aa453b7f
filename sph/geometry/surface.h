#pragma once
/// @file
/// The free surface of the soil seen from a point: how high the soil reaches on the vertical through
/// it (along −g), for the geostatic stress under a surface that is not flat.
#include <span>

#include "sph/geometry/layout.h"

namespace soilsph::sph {

/// The height (along −`down`, as Geometry::height measures it) of the highest point of the regions'
/// outlines on the line through `p` parallel to `down`, or −∞ if that line meets no outline.
/// The union of the regions is taken as it is drawn: the highest outline crossing wins, so under an
/// overhang (soil, air, soil on one vertical) the top of the highest soil counts and the air between
/// is counted as if it were soil (the stress is then that of the full column above, an upper bound).
/// A vertical outline edge through `p` counts with its higher end. On a horizontal outline edge the
/// height is that of its end points exactly (no interpolation): a box's top gives the same number
/// as the flat surface Geometry::surface_level.
double surface_height_above(std::span<const Region> regions, Vec2 down, Vec2 p);

}  // namespace soilsph::sph
