#include "sph/geometry/read_particles_3d.h"

#include <algorithm>

#include "sph/geometry/particle_csv.h"

namespace soilsph::sph {

std::vector<ParticleRegion3> read_particle_file_3d(const std::string& path, const std::string& region_name,
                                                   double dx, const std::string& scene_source,
                                                   const std::vector<std::string>& materials) {
  std::vector<ParticleRegion3> regions;
  read_particle_rows<3>(
      path, region_name, dx, scene_source, materials, [&](Vec3 p, const std::string& material) {
        auto region = std::find_if(regions.begin(), regions.end(),
                                   [&](const ParticleRegion3& r) { return r.material == material; });
        if (region == regions.end()) {
          regions.push_back({.material = material,
                             .name = region_name + " (" + path + ", " + material + ")",
                             .positions = {},
                             .bounds = {p, p}});
          region = regions.end() - 1;
        }
        region->positions.push_back(p);
        region->bounds = merged(region->bounds, Box3{p, p});
      });
  const Vec3 half{0.5 * dx, 0.5 * dx, 0.5 * dx};
  for (ParticleRegion3& r : regions) r.bounds = {r.bounds.lo - half, r.bounds.hi + half};
  return regions;
}

}  // namespace soilsph::sph
