#include "sph/analysis/gauges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "constitutive/parameters.h"
#include "constitutive/tensor.h"

namespace soilsph::sph {

namespace {
/// The soil particle nearest `at` at t = 0, and its distance.
template <int dim>
std::pair<std::size_t, double> nearest_at_start(const ParticlesOf<dim>& p, Vec<dim> at) {
  std::size_t best = 0;
  double best2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const Vec<dim> d = p.start_position(i) - at;
    const double d2 = dot(d, d);
    if (d2 < best2) best = i, best2 = d2;
  }
  return {best, std::sqrt(best2)};
}

/// Particle i's velocity at t^n: the mean of v^{n−½} and v^{n+½}, times `factor`.
template <int dim>
Vec<dim> mean_velocity(const ParticlesOf<dim>& p, std::size_t i, const std::array<std::span<const double>, dim>& v_next,
                       double factor) {
  if constexpr (dim == 2)
    return factor * Vec2{p.vx[i] + v_next[0][i], p.vy[i] + v_next[1][i]};
  else
    return factor * Vec3{p.vx[i] + v_next[0][i], p.vy[i] + v_next[1][i], p.vz[i] + v_next[2][i]};
}

template <int dim>
GaugeReadingOf<dim> particle_reading(const ParticlesOf<dim>& p, std::size_t i,
                                     const std::array<std::span<const double>, dim>& v_next) {
  const Mat3& s = p.state[i].stress;
  return {p.position(i), p.position(i) - p.start_position(i), mean_velocity<dim>(p, i, v_next, 0.5), mean_pressure(s),
          deviatoric_stress(s)};
}

/// The index of the soil particle with `id`: its own index while the arrays keep the order they
/// were built in, else found by search.
template <int dim>
std::size_t index_of(const ParticlesOf<dim>& p, std::uint64_t id) {
  if (id < p.soil_count && p.id[id] == id) return id;
  return static_cast<std::size_t>(std::find(p.id.begin(), p.id.end(), id) - p.id.begin());
}

std::string coordinates_text(Vec2 v) {
  std::ostringstream out;
  out << '[' << v.x << ", " << v.y << ']';
  return out.str();
}
std::string coordinates_text(Vec3 v) {
  std::ostringstream out;
  out << '[' << v.x << ", " << v.y << ", " << v.z << ']';
  return out.str();
}
}  // namespace

template <int dim>
GaugeSetOf<dim>::GaugeSetOf(std::vector<GaugeOf<dim>> gauges, const ParticlesOf<dim>& p, double spacing,
                            const SmoothingKernel<dim>& kernel, const std::string& source)
    : gauges_(std::move(gauges)), particle_(gauges_.size(), 0), kernel_(kernel) {
  for (std::size_t g = 0; g < gauges_.size(); ++g) {
    if (gauges_[g].kind != GaugeKind::Particle) continue;
    const auto [i, distance] = nearest_at_start(p, gauges_[g].position);
    if (p.soil_count == 0 || distance > spacing) {
      std::ostringstream msg;
      msg << source << ": [[gauges]] " << gauges_[g].name << ": no soil particle within one spacing (" << spacing
          << " m) of position " << coordinates_text(gauges_[g].position)
          << " at t = 0 (a \"particle\" gauge follows the soil particle there; put it inside the soil, or use "
             "kind = \"point\")";
      throw ParameterError(msg.str());
    }
    particle_[g] = p.id[i];
  }
}

template <int dim>
std::vector<GaugeReadingOf<dim>> GaugeSetOf<dim>::read(const ParticlesOf<dim>& p,
                                                       const std::array<std::span<const double>, dim>& v_next) const {
  std::vector<GaugeReadingOf<dim>> readings;
  readings.reserve(gauges_.size());
  const double support2 = kernel_.support() * kernel_.support();
  for (std::size_t g = 0; g < gauges_.size(); ++g) {
    if (gauges_[g].kind == GaugeKind::Particle) {
      readings.push_back(particle_reading<dim>(p, index_of(p, particle_[g]), v_next));
      continue;
    }
    const Vec<dim> at = gauges_[g].position;
    double weight = 0.0;
    Vec<dim> displacement, velocity;
    Mat3 stress = Mat3::Zero();  // averaged as a tensor: q of the mean stress, not the mean of q
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      const Vec<dim> d = at - p.position(i);
      const double r2 = dot(d, d);
      if (r2 >= support2) continue;
      const double wv = kernel_.value(std::sqrt(r2)) * p.mass[i] / p.density[i];
      weight += wv;
      displacement = displacement + wv * (p.position(i) - p.start_position(i));
      velocity = velocity + mean_velocity<dim>(p, i, v_next, 0.5 * wv);
      stress += wv * p.state[i].stress;
    }
    const double inv = weight > 0.0 ? 1.0 / weight : std::numeric_limits<double>::quiet_NaN();
    stress *= inv;
    readings.push_back({at, inv * displacement, inv * velocity, mean_pressure(stress), deviatoric_stress(stress)});
  }
  return readings;
}

template class GaugeSetOf<2>;
template class GaugeSetOf<3>;

}  // namespace soilsph::sph
