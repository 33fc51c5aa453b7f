#include "sph/solver.h"

#include "sph/initial_state.h"
#include "sph/setup_parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace soilsph::sph {

namespace {
/// The box the soil stays in (blow_up.h): around the walls and their ghost layers (where they move
/// to included) and the soil, up to twice the soil's height above its base, widened by the kernel
/// support 2h. For the column: the floor from its far end to the fixed wall's ghost layers, and
/// twice the column's height.
Domain domain(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double behind = g.boundary_layers * g.particle_spacing, support = 2.0 * g.smoothing_length();
  Domain d{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  const auto include = [&](Vec2 v, double margin) {
    d.x_min = std::min(d.x_min, v.x - margin), d.x_max = std::max(d.x_max, v.x + margin);
    d.y_min = std::min(d.y_min, v.y - margin), d.y_max = std::max(d.y_max, v.y + margin);
  };
  for (const Wall& w : g.layout.walls)
    for (const Vec2& v : w.points) {
      include(v, behind + support);
      if (w.motion.moves()) include(v + w.motion.displacement(w.motion.end), behind + support);
    }
  for (const Region& r : g.layout.regions)
    for (const Vec2& v : r.outline) include(v, support);
  // Soil thrown up to twice its height above its base; a scene of regions also that far sideways
  // (the column's soil stays between its fixed wall and the floor's far end).
  const double up = 2.0 * g.soil_extent.height + support;
  d.y_max = std::max(d.y_max, g.base_level + up);
  if (!g.column)
    for (const Region& r : g.layout.regions)
      for (const Vec2& v : r.outline) include(v, up);
  return d;
}

/// The lowest wall along −g (the column: its floor surface, −Δp/2), the datum of the potential energy.
double potential_datum(const Scene& scene) {
  const Geometry& g = scene.geometry;
  double datum = g.base_level - 0.5 * g.particle_spacing;
  for (const Wall& w : g.layout.walls)
    for (const Vec2& v : w.points) datum = std::min(datum, g.height(v));
  return datum;
}

/// The symmetry lines as the planes their images reflect across: along x or y (read_layout.cpp
/// refuses another), so a line along y is the plane x = its x, the soil on its left.
std::vector<SymmetryPlane> symmetry_planes(const Scene& scene) {
  std::vector<SymmetryPlane> planes;
  const std::vector<Wall>& walls = scene.geometry.layout.walls;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (!walls[w].symmetry_plane) continue;
    const Vec2 a = walls[w].points.front(), along = walls[w].points.back() - a;
    const Vec2 inward{-along.y, along.x};
    const int axis = std::abs(inward.x) > std::abs(inward.y) ? 0 : 1;
    planes.push_back({.axis = axis,
                      .offset = axis == 0 ? a.x : a.y,
                      .side = (axis == 0 ? inward.x : inward.y) > 0.0 ? 1.0 : -1.0,
                      .wall = static_cast<int>(w)});
  }
  return planes;
}
}  // namespace

template <int dim>
MaterialGroups material_groups(const std::vector<Material>& materials, const ParticlesOf<dim>& p) {
  MaterialGroups groups;
  std::size_t begin = 0;
  for (std::size_t k = 0; k < materials.size(); ++k) {
    std::size_t end = begin;
    while (end < p.soil_count && p.material[end] == static_cast<int>(k)) ++end;
    const Material& m = materials[k];
    groups.push_back({.model = m,
                      .fallback = std::visit([](const auto& model) { return Material(fallback_model(model)); }, m),
                      .begin = begin,
                      .end = end,
                      .pressure_dependent = stiffness_follows_state(m)});
    begin = end;
  }
  if (begin != p.soil_count)
    throw std::logic_error(
        "material_groups: the soil particles are not ordered by material (initial_state.h)");
  return groups;
}
template MaterialGroups material_groups(const std::vector<Material>&, const ParticlesOf<2>&);
template MaterialGroups material_groups(const std::vector<Material>&, const ParticlesOf<3>&);

SolverSetup make_solver_setup(const Scene& scene) {
  return solver_setup<2>(scene, {.guard = wall_guard(scene),
                                 .walls = wall_motions(scene),
                                 .potential_datum = potential_datum(scene),
                                 .domain = domain(scene),
                                 .symmetry_planes = symmetry_planes(scene),
                                 .boundary_layers = static_cast<double>(scene.geometry.boundary_layers)});
}

}  // namespace soilsph::sph
