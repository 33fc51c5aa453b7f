#pragma once
/// @file
/// Soil particles of space imported from a CSV file (x, y, z, region): shapes made elsewhere, at
/// positions that need not lie on the scene's lattice; the 3D counterpart of read_particles.h.
#include <string>
#include <vector>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// The imported particles of one material.
struct ParticleRegion3 {
  std::string material;         ///< the [materials.NAME] they are made of
  std::string name;             ///< "REGION (FILE, MATERIAL)", for messages
  std::vector<Vec3> positions;  ///< m, in file order
  Box3 bounds;                  ///< the box of the particles' cells (each Δp wide around its centre)
};

/// Reads `path` (a header row `x,y,z,region`, then one particle a row: x, y, z in m, `region` the
/// [materials.NAME] it is made of, or empty where the scene has one material) into one region per
/// material named, in the order of first appearance. Throws ParameterError naming the file and
/// line: a missing or unreadable file, a wrong header, a row without four fields or with a number
/// that does not parse or is not finite or beyond 10⁴ m, an unknown material, two particles closer
/// than Δp/2, or no particle at all; the two messages that depend on the scene (its materials, its
/// particle_spacing) name `scene_source`, the scene file that reads the particles.
std::vector<ParticleRegion3> read_particle_file_3d(const std::string& path, const std::string& region_name,
                                                   double spacing, const std::string& scene_source,
                                                   const std::vector<std::string>& materials);

}  // namespace soilsph::sph
