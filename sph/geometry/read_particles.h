#pragma once
/// @file
/// Soil particles imported from a CSV file (a `[[regions]]` entry with shape = "particles",
/// docs/reference/scenes.md): shapes made elsewhere, at positions that need not lie on the scene's lattice.
#include <string>
#include <vector>

#include "sph/geometry/layout.h"

namespace soilsph::sph {

/// Reads `path` (a header row `x,y,region`, then one particle a row: x and y in m, `region` the
/// [materials.NAME] it is made of, or empty where the scene has one material) into one region per
/// material named, in the order of first appearance, each with the box of its particles' cells as
/// outline. Throws ParameterError naming the file and line: a missing or unreadable file, a wrong
/// header, a row without three fields or with a number that does not parse or is not finite or
/// beyond 10⁴ m, an unknown material, two particles closer than Δp/2, or no particle at all. The
/// messages of the two that depend on the scene (its materials, its particle_spacing) name
/// `scene_source`, the scene file that reads the particles.
std::vector<Region> read_particle_file(const std::string& path, const std::string& region_name,
                                       double spacing, const std::string& scene_source,
                                       const std::vector<std::string>& materials);

}  // namespace soilsph::sph
