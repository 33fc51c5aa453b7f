#include "sph/geometry/regions_3d.h"

#include <cmath>
#include <numbers>
#include <set>
#include <tuple>
#include <type_traits>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"

namespace soilsph::sph {

namespace {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

double box_volume(const Box3& b) {
  return (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z);
}
}  // namespace

Box3 region_bounds(const SoilRegion3& region) {
  return std::visit(Overloaded{[](const ParticleCloud3& c) { return c.cells; },
                               [](const auto& solid) { return solid.bounds(); }},
                    region.shape);
}

double estimated_particles(const SoilRegion3& region, double spacing) {
  const double cell = spacing * spacing * spacing;
  return std::visit(
      Overloaded{
          [&](const SoilBox& b) { return box_volume(b.box) / cell; },
          [&](const ColumnCylinder& c) {
            return std::numbers::pi * c.radius * c.radius * c.share() * c.height /
                   cell;  // whole cells fill it
          },
          [&](const Extrusion& e) { return std::abs(signed_area(e.outline)) * (e.z_max - e.z_min) / cell; },
          [&](const StlSolid& s) { return s.volume() / cell; },
          [](const ParticleCloud3& c) { return static_cast<double>(c.positions.size()); }},
      region.shape);
}

std::vector<SoilNode3> soil_nodes_3d(const std::vector<SoilRegion3>& regions, const Lattice3& lattice,
                                     const std::string& source) {
  std::vector<SoilNode3> nodes;
  std::set<std::tuple<long long, long long, long long>>
      taken;  // (i, j, k) of earlier regions (overlaps only)
  const Vec3 o = lattice.origin;
  const double dx = lattice.spacing;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const int region = static_cast<int>(r);
    const std::size_t before = nodes.size();
    std::visit(Overloaded{[&](const ParticleCloud3& cloud) {
                            for (const Vec3& p : cloud.positions) nodes.push_back({p, region});
                          },
                          [&](const auto& solid) {
                            for (const Vec3& p : lattice_nodes_inside(solid, lattice)) {
                              const auto index = std::make_tuple(std::llround((p.x - o.x) / dx),
                                                                 std::llround((p.y - o.y) / dx),
                                                                 std::llround((p.z - o.z) / dx));
                              if (regions.size() > 1 && !taken.insert(index).second) continue;
                              nodes.push_back({p, region});
                            }
                          }},
               regions[r].shape);
    if (nodes.size() == before)
      throw ParameterError(source + ": " + regions[r].name +
                           " holds no particle of the lattice at particle_spacing = " + format_number(dx) +
                           " m (smaller than a spacing, or covered by earlier regions)");
  }
  return nodes;
}

}  // namespace soilsph::sph
