#include "sph/output/histories.h"

#include <cmath>

#include "sph/analysis/boundary_forces.h"
#include "sph/analysis/energy.h"

namespace soilsph::sph {

namespace {
/// The walls a run reports, by index: in the plane those present at t = 0; in space every wall.
std::vector<std::size_t> walls_present(const Scene& scene) {
  const Layout& layout = scene.geometry.layout;
  std::vector<std::size_t> walls;
  for (std::size_t w = 0; w < layout.walls.size(); ++w)
    if (layout.walls[w].motion.removed_at > 0.0) walls.push_back(w);
  return walls;
}
std::vector<std::size_t> walls_present(const Scene3& scene) {
  std::vector<std::size_t> walls(scene.geometry.walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) walls[w] = w;
  return walls;
}

const std::string& wall_label(const Scene& scene, std::size_t w) { return scene.geometry.layout.walls[w].label; }
const std::string& wall_label(const Scene3& scene, std::size_t w) { return scene.geometry.walls[w].label; }
std::size_t wall_count(const Scene& scene) { return scene.geometry.layout.walls.size(); }
std::size_t wall_count(const Scene3& scene) { return scene.geometry.walls.size(); }

/// What part of the soil the energy history sums over.
std::string energy_scope(const Scene&) { return "per metre of thickness (plane strain)"; }
std::string energy_scope(const Scene3& scene) {
  const Geometry3& g = scene.geometry;
  if (g.shape == Geometry3::Shape::Slab) return "of the slab simulated";
  if (g.shape == Geometry3::Shape::Regions) return "of the soil simulated";
  if (g.azimuth_span_deg >= 360.0) return "of the whole column";
  return g.azimuth_span_deg >= 180.0 ? "of the half column simulated (x2 for the whole column)"
                                     : "of the quarter column simulated (x4 for the whole column)";
}

template <int dim>
std::vector<std::string> gauge_names(const std::vector<GaugeOf<dim>>& gauges) {
  std::vector<std::string> names;
  for (const GaugeOf<dim>& g : gauges) names.push_back(g.name);
  return names;
}
}  // namespace

template <int dim>
HistoriesOf<dim>::HistoriesOf(const SceneOf<dim>& scene, const ParticlesOf<dim>& particles,
                              const SmoothingKernel<dim>& kernel)
    : scene_(scene),
      walls_(walls_present(scene)),
      gauges_(scene.gauges, particles, scene.geometry.particle_spacing, kernel, scene.source) {}

template <int dim>
void HistoriesOf<dim>::open(const std::filesystem::path& dir, double resume_time) {
  std::vector<std::string> walls, gauges = gauge_names(scene_.gauges);
  for (const std::size_t w : walls_) walls.push_back(wall_label(scene_, w));
  const std::string scope = energy_scope(scene_);
  writer_.emplace(resume_time >= 0.0
                      ? HistoryWriterOf<dim>::continuing(dir, std::move(walls), std::move(gauges), scope, resume_time)
                      : HistoryWriterOf<dim>(dir, std::move(walls), std::move(gauges), scope));
  const double interval = scene_.output.history_interval;
  if (writer_->last_sample() >= 0.0) first_sample_ = interval * (std::floor(writer_->last_sample() / interval) + 1.0);
}

template <int dim>
void HistoriesOf<dim>::operator()(const StepSampleOf<dim>& s) {
  const std::vector<Vec<dim>> all = boundary_forces(s.particles, s.neighbours, s.momentum, wall_count(scene_));
  std::vector<Vec<dim>> forces;
  for (const std::size_t w : walls_) forces.push_back(all[w]);
  writer_->write(s.time, forces, gauges_.read(s.particles, s.v_next),
                 mechanical_energy<dim>(s.particles, s.v_next, scene_.geometry.gravity));
}

template class HistoriesOf<2>;
template class HistoriesOf<3>;

}  // namespace soilsph::sph
