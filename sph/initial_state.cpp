#include "sph/initial_state.h"

#include <cmath>
#include <sstream>

namespace soilsph::sph {

namespace {
int lattice_count(double length, double spacing) {
  return static_cast<int>(std::lround(length / spacing)) + 1;
}

struct Point {
  double x, y;
  BoundaryKind kind;
};

std::vector<Point> boundary_points(const Geometry& g) {
  const double dx = g.particle_spacing;
  const int layers = g.boundary_layers;
  const double wall_top = g.column_height + 2.0 * g.smoothing_length();
  const int wall_rows = lattice_count(wall_top, dx);
  const int floor_columns = lattice_count(g.floor_length, dx) + layers;  // from W + layers·dx leftwards
  std::vector<Point> points;
  for (int k = 1; k <= layers; ++k)
    for (int c = 0; c < floor_columns; ++c)
      points.push_back({g.column_width + layers * dx - c * dx, -k * dx, BoundaryKind::NoSlipFloor});
  for (int k = 1; k <= layers; ++k)
    for (int r = 0; r < wall_rows; ++r) {
      points.push_back({g.column_width + k * dx, r * dx, BoundaryKind::FreeSlipWall});
      if (g.wall_withdrawal == WallWithdrawal::None)
        points.push_back({-k * dx, r * dx, BoundaryKind::FreeSlipWall});
    }
  return points;
}

/// The model's initial hardening state (its hook: MCC's p_c, 0 for models without one).
template <class Model>
double initial_preconsolidation(const Model& model, const Mat3& sigma, const InitialConditions& c) {
  return model.initial_preconsolidation(sigma, c.overconsolidation_ratio, c.preconsolidation_floor);
}

template <class Model>
bool inside_yield_surface(const Model& model, const State& s) {
  if constexpr (requires { model.yield(s.stress, s.pc); }) {
    return model.normalized_yield(s.stress, s.pc) <= 1e-9;
  } else {
    return true;
  }
}

Mat3 geostatic_stress(const Geometry& g, double density, double k0, double y) {
  const double vertical = -density * g.gravity * (g.column_height + 0.5 * g.particle_spacing - y);
  Mat3 sigma = Mat3::Zero();
  sigma(0, 0) = sigma(2, 2) = k0 * vertical;
  sigma(1, 1) = vertical;
  return sigma;
}
}  // namespace

Particles build_particles(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double dx = g.particle_spacing;
  const double rho = density(scene.material);
  const int nx = lattice_count(g.column_width, dx), ny = lattice_count(g.column_height, dx);
  const std::vector<Point> boundary = boundary_points(g);

  Particles p;
  p.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), boundary.size());
  std::size_t i = 0;
  for (int r = 0; r < ny; ++r)
    for (int c = 0; c < nx; ++c, ++i) {
      p.x[i] = c * dx;
      p.y[i] = r * dx;
      p.layer[i] = static_cast<int>((r * dx + 0.5 * dx) / scene.output.layer_thickness);
    }
  for (const Point& b : boundary) {
    p.x[i] = b.x;
    p.y[i] = b.y;
    p.boundary_kind[i - p.soil_count] = b.kind;
    ++i;
  }
  std::fill(p.density.begin(), p.density.end(), rho);
  std::fill(p.mass.begin(), p.mass.end(), rho * dx * dx);
  return p;
}

void set_geostatic_state(Particles& p, const Scene& scene) {
  const double rho = density(scene.material);
  std::visit(
      [&](const auto& model) {
        for (std::size_t i = 0; i < p.soil_count; ++i) {
          State& s = p.state[i];
          s = State{};
          s.stress = geostatic_stress(scene.geometry, rho, scene.initial.lateral_stress_ratio, p.y[i]);
          s.pc = initial_preconsolidation(model, s.stress, scene.initial);
          if (!inside_yield_surface(model, s)) {
            std::ostringstream msg;
            msg << scene.source << ": the geostatic stress at y = " << p.y[i]
                << " m lies outside the yield surface; [initial] lateral_stress_ratio = "
                << scene.initial.lateral_stress_ratio << " is not admissible for this material";
            throw ParameterError(msg.str());
          }
          p.sxx[i] = s.stress(0, 0), p.syy[i] = s.stress(1, 1), p.sxy[i] = s.stress(0, 1);
        }
      },
      scene.material);
}

double smallest_admissible_lateral_stress_ratio(const Material& material, const Geometry& geometry) {
  return std::visit(
      [&](const auto& model) {
        const auto admissible = [&](double k0) {
          State s;
          s.stress = geostatic_stress(geometry, model.params().density, k0, 0.0);
          s.pc = initial_preconsolidation(model, s.stress, {k0, 1.0, 0.0});
          return inside_yield_surface(model, s);
        };
        double lo = 0.0, hi = 1.0;  // inadmissible at lo (or lo = 0), admissible at hi
        if (admissible(1e-12)) return 0.0;
        for (int k = 0; k < 60 && hi - lo > 1e-12; ++k) (admissible(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
        return hi;
      },
      material);
}

double largest_initial_pressure(const Scene& scene) {
  const Mat3 base =
      geostatic_stress(scene.geometry, density(scene.material), scene.initial.lateral_stress_ratio, 0.0);
  return mean_pressure(base);
}

WallGuard wall_guard(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double half = 0.5 * g.particle_spacing;
  WallGuard guard{-half, g.column_width + half, std::nullopt};
  if (g.wall_withdrawal == WallWithdrawal::None) guard.left_wall_x = -half;
  return guard;
}

}  // namespace soilsph::sph
