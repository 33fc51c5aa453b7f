#include "sph/initial_state_3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "sph/geometry/planar_ghosts.h"
#include "sph/geostatic_state.h"
#include "sph/stages/boundaries.h"

namespace soilsph::sph {

namespace {
/// μ of a wall: the 2D wall's one formula (stages/boundaries.h), from the same kind and angle.
double friction_coefficient(const Wall3& wall) {
  Wall plane_wall;
  plane_wall.kind = wall.kind;
  plane_wall.friction_angle = wall.friction_angle;
  return wall_friction_coefficient(plane_wall);
}

/// The image signs of ghost b (ThirdAxisArrays<3>::image_sign_x): the product of the reflections
/// across every free-slip wall other than its own that it also lies behind, within the ghost layers
/// (the floor's edge below a free-slip side wall, its corner below two). Such a wall must be normal
/// to an axis, so that the reflections commute and their product is a sign per axis. Throws
/// ParameterError for another. A symmetry plane counts for none: the ghost's row holds the soil's
/// mirror images behind it (stages/mirror_images.h), so its average is the mirror already. A wall
/// that moves or goes images no ghost: its plane leaves the ghosts behind it. A moving wall's ghost
/// keeps its images only while it moves parallel to the planes that image it: another motion is an
/// error.
Vec3 image_signs(const Geometry3& g, const GhostPoint3& b, const std::string& source) {
  const double depth = (g.boundary_layers + 1e-9) * g.particle_spacing;
  const Wall3& own = g.walls[static_cast<std::size_t>(b.wall)];
  Vec3 sign{1.0, 1.0, 1.0};
  for (std::size_t w = 0; w < g.walls.size(); ++w) {
    const Wall3& wall = g.walls[w];
    // A symmetry plane's mirror is in the ghost's row already: the soil's images (mirror_images.h).
    if (static_cast<int>(w) == b.wall || wall.kind != WallKind::FreeSlip || wall.motion.changes() ||
        wall.symmetry_plane)
      continue;
    const double height = wall.plane.height_above(b.position);
    if (!(height < -1e-9 * g.particle_spacing && height > -depth)) continue;
    const int axis = axis_along(wall.plane.inward);
    if (axis < 0)
      throw ParameterError(source + ": the free-slip wall \"" + wall.label +
                           "\" meets another wall's ghosts but is not normal to an axis (a corner of two such "
                           "planes is mirrored only where each is normal to x, y or z)");
    if (own.motion.moves() && component(own.motion.velocity, axis) != 0.0)
      throw ParameterError(
          source + ": the wall \"" + own.label + "\" moves across the free-slip wall \"" + wall.label +
          "\", behind which some of its ghosts lie: they would leave it (a moving wall's ghosts "
          "may move only parallel to the free-slip walls they lie behind)");
    sign = with_component(sign, axis, -component(sign, axis));
  }
  return sign;
}

/// Several materials: each soil particle's density and mass ρ Δp³ from its own material, and each
/// ghost's those of the soil particle nearest to it, as in 2D (initial_state.cpp).
void set_material_densities(ParticlesOf<3>& p, const Scene3& scene) {
  const double dx = scene.geometry.particle_spacing, cell = dx * dx * dx;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    p.density[i] = density(scene.materials[static_cast<std::size_t>(p.material[i])]);
    p.mass[i] = p.density[i] * cell;
  }
  for (std::size_t i = p.soil_count; i < p.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    const Vec3 ghost = p.position(i);
    for (std::size_t j = 0; j < p.soil_count; ++j) {
      const Vec3 d = p.position(j) - ghost;
      if (const double d2 = dot(d, d); d2 < nearest) nearest = d2, p.density[i] = p.density[j];
    }
    p.mass[i] = p.density[i] * cell;
  }
}

/// What lies above each soil particle in its lattice column (the soil particles at the same x and z,
/// to within Δp/2 of the lattice; gravity is along −y in space):
/// - `surface`: the top of the column's soil, its highest particle + Δp/2 (the top of its cell), the
///   local free surface of [initial] stress = "local-surface";
/// - `excess`: Δp Σ_k n_k (ρ_k − ρ_i) over the materials k above it, n_k their particles there, so
///   that ρ_i (surface − height) plus it is the weight of the soil above per unit area over |g|,
///   each layer with its own density; exactly 0 where they all have the particle's density (as 2D's
///   overburden_density_excess).
struct ColumnOverburden {
  std::vector<double> surface, excess;
};
ColumnOverburden column_overburden(const ParticlesOf<3>& p, const Geometry3& g, const std::vector<double>& rho) {
  const double dx = g.particle_spacing;
  const Vec3 o = g.lattice.origin;
  std::vector<std::size_t> order(p.soil_count);
  std::vector<std::pair<long long, long long>> column(p.soil_count);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    order[i] = i;
    column[i] = {std::llround((p.x[i] - o.x) / dx), std::llround((p.z[i] - o.z) / dx)};
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (column[a] != column[b]) return column[a] < column[b];
    return p.y[a] > p.y[b];  // from the top down
  });
  ColumnOverburden above{std::vector<double>(p.soil_count), std::vector<double>(p.soil_count, 0.0)};
  std::vector<std::size_t> count(rho.size());  // particles of each material above, in this column
  double top = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k], own = static_cast<std::size_t>(p.material[i]);
    if (k == 0 || column[i] != column[order[k - 1]]) {
      std::fill(count.begin(), count.end(), 0);
      top = g.height(p.position(i)) + 0.5 * dx;
    }
    above.surface[i] = top;
    for (std::size_t m = 0; m < rho.size(); ++m)
      above.excess[i] += static_cast<double>(count[m]) * dx * (rho[m] - rho[own]);
    ++count[own];
  }
  return above;
}
}  // namespace

ParticlesOf<3> build_particles_3d(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  const double dx = g.particle_spacing, rho = density(scene.material), mass = rho * dx * dx * dx;
  std::vector<SoilNode3> soil = soil_nodes_3d(g.regions, g.lattice, scene.source);
  const auto material_of = [&](const SoilNode3& n) {
    return scene.region_material[static_cast<std::size_t>(n.region)];
  };
  // Each material's particles contiguous (the step visits each model once per step, solver.h); the
  // stable sort keeps the lattice order within a material, and the whole order with one material.
  std::stable_sort(soil.begin(), soil.end(),
                   [&](const SoilNode3& a, const SoilNode3& b) { return material_of(a) < material_of(b); });
  // A node behind two walls is claimed by the first wall listed (planar_ghosts.h): the walls that
  // stay are listed before those that move or go, which would otherwise carry a wall's edge and
  // corner ghosts away (the slab's symmetry planes beside its lifted gate).
  std::vector<std::size_t> claiming;
  for (const bool changes : {false, true})
    for (std::size_t w = 0; w < g.walls.size(); ++w)
      if (g.walls[w].motion.changes() == changes) claiming.push_back(w);
  std::vector<PlanarWall> planes;
  std::vector<bool> mirrored;
  for (const std::size_t w : claiming) planes.push_back(g.walls[w].plane), mirrored.push_back(g.walls[w].symmetry_plane);
  std::vector<GhostPoint3> ghosts = planar_ghost_points(planes, g.lattice, g.boundary_layers, mirrored);
  for (GhostPoint3& b : ghosts) b.wall = static_cast<int>(claiming[static_cast<std::size_t>(b.wall)]);

  double lowest = std::numeric_limits<double>::infinity();  // the bottom of the lowest particle's cell
  for (const SoilNode3& n : soil) lowest = std::min(lowest, g.height(n.position) - 0.5 * dx);
  ParticlesOf<3> p;
  p.resize(soil.size(), ghosts.size());
  for (std::size_t i = 0; i < soil.size(); ++i) {
    const Vec3 at = soil[i].position;
    p.x[i] = p.x0[i] = at.x;
    p.y[i] = p.y0[i] = at.y;
    p.z[i] = p.z0[i] = at.z;
    p.layer[i] = static_cast<int>((g.height(at) - lowest) / scene.output.layer_thickness);
    p.material[i] = material_of(soil[i]);
  }
  for (std::size_t k = 0; k < ghosts.size(); ++k) {
    const GhostPoint3& b = ghosts[k];
    const Wall3& wall = g.walls[static_cast<std::size_t>(b.wall)];
    const std::size_t i = soil.size() + k;
    p.x[i] = b.position.x, p.y[i] = b.position.y, p.z[i] = b.position.z;
    p.boundary_kind[k] = wall.kind;
    p.wall_nx[k] = b.inward.x, p.wall_ny[k] = b.inward.y, p.wall_nz[k] = b.inward.z;
    p.wall_friction[k] = friction_coefficient(wall);
    p.wall_stick[k] = wall.kind == WallKind::NoSlip ? 1.0 : 0.0;
    p.wall_id[k] = b.wall;
    const Vec3 sign = image_signs(g, b, scene.source);
    p.image_sign_x[k] = sign.x, p.image_sign_y[k] = sign.y, p.image_sign_z[k] = sign.z;
  }
  std::fill(p.density.begin(), p.density.end(), rho);
  std::fill(p.mass.begin(), p.mass.end(), mass);
  if (scene.materials.size() > 1) set_material_densities(p, scene);
  wall_motions(scene).set_velocities(p, 0.0);
  return p;
}

WallMotionsOf<3> wall_motions(const Scene3& scene) {
  WallMotionsOf<3> motions;
  for (const Wall3& w : scene.geometry.walls) motions.add(w.motion);
  return motions;
}

Mat3 geostatic_stress_3d(const Geometry3& g, double density, double k0, double surface, double height) {
  // σ_v (K0 (I − ĝĝ) + ĝĝ); "+ 0.0" turns a −0 of the products into +0 (no −0 shear in output).
  const double vertical = -density * g.gravity_magnitude() * (surface - height);
  const Vec3 d = g.down();
  Mat3 sigma;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double identity = a == b ? 1.0 : 0.0, dd = component(d, a) * component(d, b);
      sigma(a, b) = vertical * (k0 * (identity - dd) + dd) + 0.0;
    }
  return sigma;
}

ParticlesOf<3> geostatic_particles(const Scene3& scene) {
  ParticlesOf<3> p = build_particles_3d(scene);
  set_geostatic_state_3d(p, scene);
  return p;
}

void set_geostatic_state_3d(ParticlesOf<3>& p, const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  const bool several = scene.materials.size() > 1, local = scene.initial.stress != InitialStress::FlatSurface;
  std::vector<double> rho_of;
  for (const Material& m : scene.materials) rho_of.push_back(density(m));
  const ColumnOverburden above = several || local ? column_overburden(p, g, rho_of) : ColumnOverburden{};
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const double rho = rho_of[k], k0 = scene.initial.material_lateral_stress_ratio[k];
    std::visit(
        [&](const auto& model) {
          for (std::size_t i = 0; i < p.soil_count; ++i) {
            if (p.material[i] != static_cast<int>(k)) continue;
            const Vec3 at{p.x[i], p.y[i], p.z[i]};
            const double height = g.height(at), surface = local ? above.surface[i] : g.surface_level;
            // One material: ρ (surface − height). Several: the mean density of the soil above.
            const double overburden = several && above.excess[i] != 0.0 ? rho + above.excess[i] / (surface - height) : rho;
            const std::optional<State> state =
                geostatic_state(model, geostatic_stress_3d(g, overburden, k0, surface, height), scene.initial);
            if (!state) {
              std::ostringstream position;
              position << "(" << at.x << ", " << at.y << ", " << at.z << ")";
              throw ParameterError(
                  inadmissible_geostatic_message(scene.source, position.str(), scene.material_table(k), k0));
            }
            const Mat3& s = (p.state[i] = *state).stress;
            p.sxx[i] = s(0, 0), p.syy[i] = s(1, 1), p.szz[i] = s(2, 2);
            p.sxy[i] = s(0, 1), p.sxz[i] = s(0, 2), p.syz[i] = s(1, 2);
          }
        },
        scene.materials[k]);
  }
}

double smallest_admissible_lateral_stress_ratio_3d(const Material& material, const Geometry3& geometry) {
  return smallest_admissible_lateral_stress_ratio(material, [&](double density, double k0) {
    return geostatic_stress_3d(geometry, density, k0, geometry.surface_level, geometry.base_level);
  });
}

double largest_initial_pressure(const Scene3& scene) {
  // Several materials: the heaviest one's weight and the largest K0, an upper bound (as in 2D).
  const Geometry3& g = scene.geometry;
  double rho = 0.0, k0 = 0.0;
  for (std::size_t k = 0; k < scene.materials.size(); ++k)
    rho = std::max(rho, density(scene.materials[k])), k0 = std::max(k0, scene.initial.material_lateral_stress_ratio[k]);
  return mean_pressure(geostatic_stress_3d(g, rho, k0, g.surface_level, g.base_level));
}

}  // namespace soilsph::sph
