#include "sph/output/histories.h"

#include <cmath>

#include "sph/analysis/boundary_forces.h"

namespace soilsph::sph {

namespace {
std::vector<std::size_t> walls_present(const Layout& layout) {
  std::vector<std::size_t> walls;
  for (std::size_t w = 0; w < layout.walls.size(); ++w)
    if (layout.walls[w].motion.removed_at > 0.0) walls.push_back(w);
  return walls;
}

std::vector<std::string> wall_labels(const Layout& layout, const std::vector<std::size_t>& walls) {
  std::vector<std::string> labels;
  for (const std::size_t w : walls) labels.push_back(layout.walls[w].label);
  return labels;
}

std::vector<std::string> gauge_names(const std::vector<Gauge>& gauges) {
  std::vector<std::string> names;
  for (const Gauge& g : gauges) names.push_back(g.name);
  return names;
}
}  // namespace

Histories::Histories(const Scene& scene, const Particles& particles, const CubicSpline& kernel)
    : scene_(scene),
      walls_(walls_present(scene.geometry.layout)),
      gauges_(scene.gauges, particles, scene.geometry.particle_spacing, kernel, scene.source) {}

void Histories::open(const std::filesystem::path& dir, double resume_time) {
  std::vector<std::string> walls = wall_labels(scene_.geometry.layout, walls_), gauges = gauge_names(scene_.gauges);
  writer_.emplace(resume_time >= 0.0 ? HistoryWriter::continuing(dir, std::move(walls), std::move(gauges), resume_time)
                                     : HistoryWriter(dir, std::move(walls), std::move(gauges)));
  const double interval = scene_.output.history_interval;
  if (writer_->last_sample() >= 0.0) first_sample_ = interval * (std::floor(writer_->last_sample() / interval) + 1.0);
}

void Histories::operator()(const StepSample& s) {
  const std::vector<Vec2> all = boundary_forces(s.particles, s.neighbours, s.momentum, scene_.geometry.layout.walls.size());
  std::vector<Vec2> forces;
  for (const std::size_t w : walls_) forces.push_back(all[w]);
  writer_->write(s.time, forces, gauges_.read(s.particles, s.v_next[0], s.v_next[1]));
}

}  // namespace soilsph::sph
