#include "sph/initial_state.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "constitutive/admissible_state.h"
#include "sph/geometry/lattice.h"
#include "sph/geometry/surface.h"
#include "sph/geostatic_state.h"
#include <sstream>

namespace soilsph::sph {

namespace {

/// σ_v = −ρ|g| (surface − height), the weight of the soil between the particle's height and the free
/// surface above it along −g, and K0 σ_v across: σ = σ_v (K0 (I − ĝĝ) + ĝĝ) in the plane,
/// σzz = K0 σ_v. With ĝ = (0, −1) these are σyy = σ_v, σxx = σzz = K0 σ_v, σxy = 0 exactly.
Mat3 geostatic_stress(const Geometry& g, double density, double k0, double surface, double height) {
  const double vertical = -density * g.gravity_magnitude() * (surface - height);
  const Vec2 d = g.down();
  Mat3 sigma = Mat3::Zero();
  sigma(0, 0) = vertical * (k0 * (1.0 - d.x * d.x) + d.x * d.x);
  sigma(1, 1) = vertical * (k0 * (1.0 - d.y * d.y) + d.y * d.y);
  sigma(0, 1) = sigma(1, 0) = vertical * (k0 * (0.0 - d.x * d.y) + d.x * d.y) + 0.0;  // + 0: no −0 shear
  sigma(2, 2) = k0 * vertical;
  return sigma;
}

/// Several materials: each soil particle's density and mass ρ Δp² from its own material, and each
/// ghost's those of the material of the soil node nearest to it (a ghost stands for the soil it
/// mirrors; its density follows the soil's each step, its mass stays).
void set_material_densities(Particles& p, const Scene& scene, const std::vector<SoilNode>& soil) {
  const double dx = scene.geometry.particle_spacing;
  std::vector<double> rho;
  for (const Material& m : scene.materials) rho.push_back(density(m));
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    p.density[i] = rho[static_cast<std::size_t>(p.material[i])];
    p.mass[i] = p.density[i] * dx * dx;
  }
  for (std::size_t i = p.soil_count; i < p.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < soil.size(); ++j) {
      const double d = norm(Vec2{p.x[i], p.y[i]} - soil[j].position);
      if (d < nearest) nearest = d, p.density[i] = p.density[j];
    }
    p.mass[i] = p.density[i] * dx * dx;
  }
}

/// Several materials: for each soil particle, Δp Σ (ρ_j − ρ_i) over the particles j above it in its
/// lattice column (the same position across −g within Δp/2), so that ρ_i (surface − height) plus it
/// is the weight of the soil above per unit area over |g|, each layer with its own density. Summed
/// as Δp Σ_k n_k (ρ_k − ρ_i) over the materials k above, so that it is exactly 0 where they all
/// have the particle's density.
std::vector<double> overburden_density_excess(const Particles& p, const Geometry& g, const std::vector<double>& rho) {
  const double dx = g.particle_spacing;
  const Vec2 d = g.down();
  std::vector<std::size_t> order(p.soil_count);
  std::vector<long long> column(p.soil_count);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    order[i] = i;
    column[i] = std::llround((d.y * p.x[i] - d.x * p.y[i]) / dx);  // position across gravity, in spacings
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (column[a] != column[b]) return column[a] < column[b];
    return g.height({p.x[a], p.y[a]}) > g.height({p.x[b], p.y[b]});  // from the top down
  });
  std::vector<double> excess(p.soil_count, 0.0);
  std::vector<std::size_t> above(rho.size());  // particles of each material above, in this column
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k == 0 || column[order[k]] != column[order[k - 1]]) std::fill(above.begin(), above.end(), 0);
    const std::size_t i = order[k], own = static_cast<std::size_t>(p.material[i]);
    for (std::size_t m = 0; m < rho.size(); ++m)
      excess[i] += static_cast<double>(above[m]) * dx * (rho[m] - rho[own]);
    ++above[own];
  }
  return excess;
}

/// The free surface above a point: flat at the top of the outline (today's column), or the local
/// top of the soil on the vertical through it (geometry/surface.h); never below the point itself.
double free_surface(const Scene& scene, Vec2 p) {
  const Geometry& g = scene.geometry;
  if (scene.initial.stress == InitialStress::FlatSurface) return g.surface_level;
  return std::max(surface_height_above(g.layout.regions, g.down(), p), g.height(p));
}

/// The lowest point of the soil's outline along −g: layer ids count from it.
double lowest_outline_height(const Geometry& g) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Region& r : g.layout.regions)
    for (const Vec2& v : r.outline) lowest = std::min(lowest, g.height(v));
  return lowest;
}
}  // namespace

Particles geostatic_particles(const Scene& scene) {
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  return p;
}

Particles build_particles(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double dx = g.particle_spacing;
  const double rho = density(scene.material);
  std::vector<SoilNode> soil = soil_nodes(g.layout, dx, scene.source);
  const auto material_of = [&](const SoilNode& n) { return scene.region_material[static_cast<std::size_t>(n.region)]; };
  // Each material's particles contiguous (the step visits each model once per step, solver.h); the
  // stable sort keeps the lattice order within a material, and the whole order with one material.
  std::stable_sort(soil.begin(), soil.end(), [&](const SoilNode& a, const SoilNode& b) { return material_of(a) < material_of(b); });
  const std::vector<GhostPoint> ghosts = ghost_points(g.layout, dx, g.boundary_layers);
  const double lowest = lowest_outline_height(g);

  Particles p;
  p.resize(soil.size(), ghosts.size());
  for (std::size_t i = 0; i < soil.size(); ++i) {
    p.x[i] = soil[i].position.x;
    p.y[i] = soil[i].position.y;
    p.x0[i] = p.x[i], p.y0[i] = p.y[i];
    p.layer[i] = static_cast<int>((g.height(soil[i].position) - lowest) / scene.output.layer_thickness);
    p.material[i] = material_of(soil[i]);
  }
  for (std::size_t k = 0; k < ghosts.size(); ++k) {
    const GhostPoint& b = ghosts[k];
    const Wall& wall = g.layout.walls[static_cast<std::size_t>(b.wall)];
    const std::size_t i = soil.size() + k;
    p.x[i] = b.position.x;
    p.y[i] = b.position.y;
    p.boundary_kind[k] = wall.kind;
    p.wall_nx[k] = b.inward.x, p.wall_ny[k] = b.inward.y;
    p.wall_friction[k] = wall_friction_coefficient(wall);
    p.wall_stick[k] = wall.kind == WallKind::NoSlip ? 1.0 : 0.0;
    p.wall_id[k] = b.wall;
  }
  std::fill(p.density.begin(), p.density.end(), rho);
  std::fill(p.mass.begin(), p.mass.end(), rho * dx * dx);
  if (scene.materials.size() > 1) set_material_densities(p, scene, soil);
  wall_motions(scene).set_velocities(p, 0.0);
  return p;
}

template <int dim>
void copy_wall_attributes(ParticlesOf<dim>& to, const ParticlesOf<dim>& from) {
  // The checkpoint's boundary is the scene's lattice ghosts, then the soil's mirror images of its
  // last search, if it has symmetry planes; the time loop rebuilds the images' own (solver.h).
  if (to.soil_count != from.soil_count || to.boundary_count() < from.boundary_count())
    throw ParameterError("the checkpoint's particles (" + std::to_string(to.soil_count) + " soil, " +
                         std::to_string(to.boundary_count()) + " boundary) are not the scene's (" +
                         std::to_string(from.soil_count) + ", " + std::to_string(from.boundary_count()) + ")");
  to.image_begin = from.size();
  const auto copy = [](const auto& a, auto& b) { std::copy(a.begin(), a.end(), b.begin()); };
  copy(from.wall_nx, to.wall_nx), copy(from.wall_ny, to.wall_ny), copy(from.wall_friction, to.wall_friction);
  copy(from.wall_stick, to.wall_stick), copy(from.wall_id, to.wall_id);
  if constexpr (dim == 3) {
    copy(from.wall_nz, to.wall_nz), copy(from.image_sign_x, to.image_sign_x);
    copy(from.image_sign_y, to.image_sign_y), copy(from.image_sign_z, to.image_sign_z);
  }
}
template void copy_wall_attributes<2>(ParticlesOf<2>&, const ParticlesOf<2>&);
template void copy_wall_attributes<3>(ParticlesOf<3>&, const ParticlesOf<3>&);

void set_geostatic_state(Particles& p, const Scene& scene) {
  const Geometry& g = scene.geometry;
  const bool several = scene.materials.size() > 1;
  std::vector<double> rho_of;
  for (const Material& m : scene.materials) rho_of.push_back(density(m));
  const std::vector<double> excess = several ? overburden_density_excess(p, g, rho_of) : std::vector<double>{};
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const double rho = density(scene.materials[k]);
    const double k0 = scene.initial.material_lateral_stress_ratio[k];
    std::visit(
        [&](const auto& model) {
          for (std::size_t i = 0; i < p.soil_count; ++i) {
            if (p.material[i] != static_cast<int>(k)) continue;
            const Vec2 at{p.x[i], p.y[i]};
            const double height = g.height(at), surface = free_surface(scene, at);
            // One material: ρ (surface − height). Several: the mean density of the soil above.
            const double overburden = several && excess[i] != 0.0 ? rho + excess[i] / (surface - height) : rho;
            const std::optional<State> state =
                geostatic_state(model, geostatic_stress(g, overburden, k0, surface, height), scene.initial);
            if (!state) {
              std::ostringstream position;
              position << "(" << p.x[i] << ", " << p.y[i] << ")";
              throw ParameterError(inadmissible_geostatic_message(scene.source, position.str(), scene.material_table(k), k0));
            }
            const State& s = p.state[i] = *state;
            p.sxx[i] = s.stress(0, 0), p.syy[i] = s.stress(1, 1), p.sxy[i] = s.stress(0, 1);
          }
        },
        scene.materials[k]);
  }
}

double smallest_admissible_lateral_stress_ratio(const Material& material, const Geometry& geometry) {
  return smallest_admissible_lateral_stress_ratio(material, [&](double density, double k0) {
    return geostatic_stress(geometry, density, k0, geometry.surface_level, geometry.base_level);
  });
}

double largest_initial_pressure(const Scene& scene) {
  // Several materials: the heaviest one's weight and the largest K0, an upper bound.
  double rho = 0.0, k0 = 0.0;
  for (std::size_t k = 0; k < scene.materials.size(); ++k)
    rho = std::max(rho, density(scene.materials[k])), k0 = std::max(k0, scene.initial.material_lateral_stress_ratio[k]);
  return mean_pressure(geostatic_stress(scene.geometry, rho, k0, scene.geometry.surface_level, scene.geometry.base_level));
}

WallGuard wall_guard(const Scene& scene) {
  const Geometry& g = scene.geometry;
  // As deep as the ghost layers, and as far past a piece's ends (its corner block).
  const double depth = (g.boundary_layers + 0.5) * g.particle_spacing;
  WallGuard guard;
  for (const Wall& w : g.layout.walls) {
    if (w.motion.removed_at <= 0.0) continue;
    for (std::size_t k = 0; k + 1 < w.points.size(); ++k) guard.faces.push_back({w.points[k], w.points[k + 1], depth, w.motion});
  }
  return guard;
}

WallMotions wall_motions(const Scene& scene) {
  WallMotions m;
  for (const Wall& w : scene.geometry.layout.walls) m.add(w.motion);
  return m;
}

}  // namespace soilsph::sph
