#include "sph/feasibility.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <type_traits>
#include <sstream>

#include "sph/geometry/polygon.h"
#include "sph/initial_state.h"
#include "sph/initial_state_3d.h"
#include "sph/solver.h"

namespace soilsph::sph {

namespace {
/// The material keys that set the P-wave speed, for a refusal caused by a tiny time step.
std::string wave_speed_keys(const Material& material, const std::string& table = "[material]") {
  const Elasticity::Kind kind = std::visit([](const auto& m) { return m.elasticity().kind(); }, material);
  return table +
         (kind == Elasticity::Kind::Constant
              ? " young_modulus, poisson_ratio and density"
              : " swelling_index, initial_void_ratio, poisson_ratio and density at the base pressure");
}

/// The keys that set the particle counts: the spacing and the geometry's size.
std::string particle_count_keys(const Geometry& g) {
  return g.column ? "[scene] particle_spacing, column_width, column_height and floor_length"
                  : "[scene] particle_spacing and the [[regions]] and [[boundaries]]";
}
std::string particle_count_keys(const Geometry3& g) {
  switch (g.shape) {
    case Geometry3::Shape::AxisymmetricColumn:
      return "[scene] particle_spacing, column_radius, column_height, floor_radius and symmetry";
    case Geometry3::Shape::Slab:
      return "[scene] particle_spacing, column_width, column_height, slab_thickness and floor_length";
    case Geometry3::Shape::Regions:
      break;
  }
  return "[scene] particle_spacing, floor_margin and the [[regions]]";
}

/// The count-independent part of an estimate: the P-wave speed, the step at rest, the steps to the
/// end time and the run time at kAssumedThroughput for `soil` + `boundary` particles.
template <int dim>
RunEstimate estimate_of(const SolverSetupOf<dim>& setup, double end_time, double soil, double boundary) {
  RunEstimate e;
  e.soil_particles = soil < 1e18 ? static_cast<std::size_t>(soil) : static_cast<std::size_t>(1e18);
  e.boundary_particles = boundary < 1e18 ? static_cast<std::size_t>(boundary) : static_cast<std::size_t>(1e18);
  e.memory_bytes = soil * kSoilBytes[dim] + boundary * kGhostBytes[dim];
  e.sound_speed = setup.sound_speed;
  e.time_step = setup.initial_time_step();
  e.steps = end_time / e.time_step;
  e.seconds = e.steps * (soil + boundary) / kAssumedThroughput;  // ghosts are paired and mirrored too
  return e;
}
}  // namespace

RunEstimate estimate_run(const Scene& scene) {
  const Geometry& g = scene.geometry;
  const double dx = g.particle_spacing, layers = g.boundary_layers;
  // Counted from the layout without building it (a spacing of 1 µm must be refused, not allocated):
  // a box's cells, a polygon's area in cells, each wall's ghost rows.
  double soil = 0.0, boundary = 0.0;
  for (const Region& r : g.layout.regions) {
    const Vec2 lo = r.outline[0], hi = r.outline[2];
    if (r.shape == Region::Shape::Particles) {
      soil += static_cast<double>(r.particles.size());
      continue;
    }
    soil += r.shape == Region::Shape::Box ? std::round((hi.x - lo.x) / dx) * std::round((hi.y - lo.y) / dx)
                                          : std::abs(signed_area(r.outline)) / (dx * dx);
  }
  for (const Wall& w : g.layout.walls) {
    if (w.motion.removed_at <= 0.0) continue;
    if (!w.strips.empty()) {
      for (const GhostStrip& s : w.strips) boundary += layers * s.count;
    } else {
      for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
        boundary += layers * (std::max(1.0, std::round(norm(w.points[k + 1] - w.points[k]) / dx)) + layers);
    }
  }
  return estimate_of(make_solver_setup(scene), g.end_time, soil, boundary);
}

RunEstimate estimate_run(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  const double dx = g.particle_spacing;
  // The soil's volume in cells (its nodes fill it one per cell, the top row included), and each
  // wall's area in cells times its ghost layers, without building either.
  double soil = 0.0;
  for (const SoilRegion3& region : g.regions) soil += estimated_particles(region, dx);
  double boundary = 0.0;
  for (const Wall3& w : g.walls) boundary += g.boundary_layers * std::abs(signed_area(w.plane.outline)) / (dx * dx);
  return estimate_of(make_solver_setup(scene), g.end_time, soil, boundary);
}

template <int dim>
RunEstimate measure_run(const SolverSetupOf<dim>& setup, const ParticlesOf<dim>& p) {
  PairList<dim> pairs;
  pairs.search(p.coordinates(), setup.kernel, p.soil_count);
  const auto n = static_cast<double>(p.size());
  RunEstimate e;
  e.soil_particles = p.soil_count;
  e.boundary_particles = p.boundary_count();
  // The step's buffers as the solver holds them (RunStatistics::workspace_bytes): v and ρ at the
  // step's end and the volume, and in space the positions at its end.
  const std::size_t buffers = dim + 2 + (dim == 3 ? 3 : 0);
  e.memory_bytes = static_cast<double>(p.bytes() + pairs.bytes()) + n * static_cast<double>(buffers * sizeof(double));
  e.sound_speed = setup.sound_speed;
  e.time_step = setup.initial_time_step();
  e.steps = setup.end_time / e.time_step;
  e.seconds = e.steps * n / kAssumedThroughput;  // an upper bound in 3D too (docs/performance.md)
  return e;
}
template RunEstimate measure_run<2>(const SolverSetupOf<2>&, const ParticlesOf<2>&);
template RunEstimate measure_run<3>(const SolverSetupOf<3>&, const ParticlesOf<3>&);

namespace {
/// Throws the message with the `--set` options it may come from: a refusal must name the option
/// that made the scene what it is, not only the file.
[[noreturn]] void refuse(const SceneSettings& scene, const std::string& message) {
  throw ParameterError(scene.source + ": " + message + overrides_note(scene.overrides));
}
}  // namespace

template <class SceneT>
void check_feasible(const SceneT& scene, const RunEstimate& e, double memory_available) {
  const auto& g = scene.geometry;
  std::ostringstream msg;
  if (!(e.time_step > 0.0) || !std::isfinite(e.time_step)) {
    msg << "the time step " << e.time_step
        << " s is not finite and positive ([numerics] cfl = " << scene.numerics.cfl
        << " times h over the P-wave speed c = " << e.sound_speed << " m/s of "
        << wave_speed_keys(scene.material) << ")";
    refuse(scene, msg.str());
  }
  // Each material must carry its weight (|v| << c in every one of them), not only the stiffest,
  // whose c sets the step: a clay of density 2e303 beside a sand was otherwise refused later, by
  // its overflowing geostatic stress, without naming its density.
  const double c = e.sound_speed, free_fall = std::sqrt(2.0 * g.gravity_magnitude() * soil_height(g));
  const double p0 = largest_initial_pressure(scene);
  for (std::size_t k = 0; k < scene.materials.size(); ++k) {
    const double ck = p_wave_speed(scene.materials[k], p0);
    if (ck > free_fall) continue;
    msg << "the soil is too soft to carry its own weight: its P-wave speed c = " << ck
        << " m/s is below the free-fall speed sqrt(2 g H) = " << free_fall
        << " m/s, where the weakly compressible scheme needs |v| << c (c from "
        << wave_speed_keys(scene.materials[k], scene.material_table(k))
        << "; a stiffer or lighter soil, or a lower [scene] gravity or column_height)";
    refuse(scene, msg.str());
  }
  if (e.memory_bytes > memory_available) {
    msg << "the scene needs about " << e.memory_bytes / 1e9 << " GB for "
        << static_cast<double>(e.soil_particles) << " soil and " << static_cast<double>(e.boundary_particles)
        << " boundary particles; this machine has " << memory_available / 1e9 << " GB (particles from "
        << particle_count_keys(g) << ")";
    refuse(scene, msg.str());
  }
  const double limit = scene.limits.max_run_hours * 3600.0;
  if (e.seconds > limit) {
    msg << "the run would take about " << human_duration(e.seconds) << " (" << e.steps << " steps of "
        << e.time_step << " s to [scene] end_time = " << g.end_time << " s with "
        << static_cast<double>(e.soil_particles) << " soil and " << static_cast<double>(e.boundary_particles)
        << " boundary particles from " << particle_count_keys(g)
        << "; the step is [numerics] cfl = " << scene.numerics.cfl
        << " times h over the P-wave speed c = " << c << " m/s of " << wave_speed_keys(scene.material)
        << "), more than [scene] max_run_hours = " << scene.limits.max_run_hours
        << " (a shorter end_time, a larger particle_spacing, or raise max_run_hours)";
    refuse(scene, msg.str());
  }
  const double frames = g.end_time / scene.output.frame_interval;
  if (frames > kMaxFrames) {
    msg << "[output] frame_interval = " << scene.output.frame_interval << " s gives " << frames
        << " frames to [scene] end_time = " << g.end_time << " s, more than " << kMaxFrames
        << " (each frame rewrites the frame indexes; a larger frame_interval)";
    refuse(scene, msg.str());
  }
}

template void check_feasible(const Scene&, const RunEstimate&, double);
template void check_feasible(const Scene3&, const RunEstimate&, double);

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e12;
}

std::string human_duration(double seconds) {
  char text[64];
  if (seconds < 120)
    std::snprintf(text, sizeof text, "%.3g s", seconds);
  else if (seconds < 7200)
    std::snprintf(text, sizeof text, "%.3g min", seconds / 60);
  else if (seconds < 2 * 86400)
    std::snprintf(text, sizeof text, "%.3g h", seconds / 3600);
  else
    std::snprintf(text, sizeof text, "%.3g days", seconds / 86400);
  return text;
}

}  // namespace soilsph::sph
