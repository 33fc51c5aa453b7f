#pragma once
/// @file
/// Plane polygons: signed area, simplicity, and which points lie inside (the lattice fill).
#include <optional>
#include <span>
#include <string>

#include "sph/geometry/vec2.h"

namespace soilsph::sph {

/// Shoelace area, > 0 for a counter-clockwise outline.
double signed_area(std::span<const Vec2> polygon);

/// Why `polygon` is not a simple, non-degenerate polygon (fewer than 3 vertices, a repeated
/// vertex, zero area, or two edges that cross or touch other than at their shared vertex), or
/// nothing if it is one.
std::optional<std::string> polygon_defect(std::span<const Vec2> polygon);

/// True if p lies inside the polygon or within `tolerance` of its outline (even-odd rule).
bool inside_or_on(std::span<const Vec2> polygon, Vec2 p, double tolerance);

/// Distance from p to the segment [a, b].
double distance_to_segment(Vec2 p, Vec2 a, Vec2 b);

}  // namespace soilsph::sph
