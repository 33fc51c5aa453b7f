#pragma once
/// @file
/// The [[boundaries]] of a 3D scene (docs/reference/scenes.md, "Three dimensions"): planar walls,
/// each a rectangle (`corner` and `edges = [a, b]`) or a polygon (`points`, and optionally `normal`),
/// with the 2D walls' kind, wall_friction_angle, removed_at, velocity, start, end and name. Every
/// key is validated as in 2D, each error naming the file, the table ("[[boundaries]] #K") and the key.
#include <toml++/toml.h>
#include <span>
#include <string>
#include <vector>

#include "sph/geometry/vec3.h"
#include "sph/scene_3d.h"

namespace soilsph::sph {

/// Appends the [[boundaries]] of `root` to `walls` (the shorthand's, whose labels they may not
/// repeat); a wall removed at t = 0 is never there in the run and goes to `withdrawn` instead
/// (Geometry3::withdrawn_walls). Returns the tables as read, defaults resolved (the scene as run).
toml::array read_boundaries_3d(const toml::table& root, const std::string& source, std::vector<Wall3>& walls,
                               std::vector<Wall3>& withdrawn);

/// `domain` grown to hold every vertex of `walls`, where it starts and where its motion ends, with
/// `margin` around each (the ghost layers and the kernel support), as the 2D scene's domain.
Box3 domain_around_walls(Box3 domain, std::span<const Wall3> walls, double margin);

}  // namespace soilsph::sph
