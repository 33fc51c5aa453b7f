#include "sph/analysis/gauges.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "constitutive/parameters.h"
#include "constitutive/tensor.h"

namespace soilsph::sph {

namespace {
/// The soil particle nearest `at` at t = 0, and its distance.
std::pair<std::size_t, double> nearest_at_start(const Particles& p, Vec2 at) {
  std::size_t best = 0;
  double best2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double dx = p.x0[i] - at.x, dy = p.y0[i] - at.y, d2 = dx * dx + dy * dy;
    if (d2 < best2) best = i, best2 = d2;
  }
  return {best, std::sqrt(best2)};
}

GaugeReading particle_reading(const Particles& p, std::size_t i, std::span<const double> vx_next,
                              std::span<const double> vy_next) {
  const Mat3& s = p.state[i].stress;
  return {{p.x[i], p.y[i]},
          {p.x[i] - p.x0[i], p.y[i] - p.y0[i]},
          {0.5 * (p.vx[i] + vx_next[i]), 0.5 * (p.vy[i] + vy_next[i])},
          mean_pressure(s),
          deviatoric_stress(s)};
}
}  // namespace

GaugeSet::GaugeSet(std::vector<Gauge> gauges, const Particles& p, double spacing, const CubicSpline& kernel,
                   const std::string& source)
    : gauges_(std::move(gauges)), particle_(gauges_.size(), 0), kernel_(kernel) {
  for (std::size_t g = 0; g < gauges_.size(); ++g) {
    if (gauges_[g].kind != Gauge::Kind::Particle) continue;
    const auto [i, distance] = nearest_at_start(p, gauges_[g].position);
    if (p.soil_count == 0 || distance > spacing) {
      std::ostringstream msg;
      msg << source << ": [[gauges]] " << gauges_[g].name << ": no soil particle within one spacing (" << spacing
          << " m) of position [" << gauges_[g].position.x << ", " << gauges_[g].position.y
          << "] at t = 0 (a \"particle\" gauge follows the soil particle there; put it inside the soil, or use "
             "kind = \"point\")";
      throw ParameterError(msg.str());
    }
    particle_[g] = i;
  }
}

std::vector<GaugeReading> GaugeSet::read(const Particles& p, std::span<const double> vx_next,
                                         std::span<const double> vy_next) const {
  std::vector<GaugeReading> readings;
  readings.reserve(gauges_.size());
  const double support2 = kernel_.support() * kernel_.support();
  for (std::size_t g = 0; g < gauges_.size(); ++g) {
    if (gauges_[g].kind == Gauge::Kind::Particle) {
      readings.push_back(particle_reading(p, particle_[g], vx_next, vy_next));
      continue;
    }
    const Vec2 at = gauges_[g].position;
    double weight = 0.0;
    Vec2 displacement, velocity;
    Mat3 stress = Mat3::Zero();  // averaged as a tensor: q of the mean stress, not the mean of q
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      const double dx = at.x - p.x[i], dy = at.y - p.y[i], r2 = dx * dx + dy * dy;
      if (r2 >= support2) continue;
      const double wv = kernel_.value(std::sqrt(r2)) * p.mass[i] / p.density[i];
      weight += wv;
      displacement = displacement + wv * Vec2{p.x[i] - p.x0[i], p.y[i] - p.y0[i]};
      velocity = velocity + (0.5 * wv) * Vec2{p.vx[i] + vx_next[i], p.vy[i] + vy_next[i]};
      stress += wv * p.state[i].stress;
    }
    const double inv = weight > 0.0 ? 1.0 / weight : std::numeric_limits<double>::quiet_NaN();
    stress *= inv;
    readings.push_back({at, inv * displacement, inv * velocity, mean_pressure(stress), deviatoric_stress(stress)});
  }
  return readings;
}

}  // namespace soilsph::sph
