#include "sph/geometry/read_particles.h"

#include <algorithm>

#include "sph/geometry/particle_csv.h"

namespace soilsph::sph {

std::vector<Region> read_particle_file(const std::string& path, const std::string& region_name, double dx,
                                       const std::string& scene_source,
                                       const std::vector<std::string>& materials) {
  std::vector<Region> regions;
  read_particle_rows<2>(path, region_name, dx, scene_source, materials,
                        [&](Vec2 p, const std::string& material) {
                          auto region = std::find_if(regions.begin(), regions.end(),
                                                     [&](const Region& r) { return r.material == material; });
                          if (region == regions.end()) {
                            regions.push_back({.shape = Region::Shape::Particles,
                                               .outline = {},
                                               .material = material,
                                               .name = region_name + " (" + path + ", " + material + ")",
                                               .particles = {}});
                            region = regions.end() - 1;
                          }
                          region->particles.push_back(p);
                        });
  for (Region& r : regions) {  // the box of the particles' cells
    Vec2 lo = r.particles.front(), hi = lo;
    for (const Vec2& v : r.particles)
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    const double h = 0.5 * dx;
    r.outline = {{lo.x - h, lo.y - h}, {hi.x + h, lo.y - h}, {hi.x + h, hi.y + h}, {lo.x - h, hi.y + h}};
  }
  return regions;
}

}  // namespace soilsph::sph
