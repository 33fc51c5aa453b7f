#pragma once
/// @file
/// Gauges: points of a scene where p, q, velocity and displacement are sampled over time
/// ([[gauges]], docs/reference/scenes.md; written to gauges.csv, docs/reference/output-formats.md),
/// in the plane or in space.
/// - A "particle" gauge is a material point: the soil particle nearest its position at t = 0, which
///   it follows by its id (ParticlesOf::id), wherever the particle sits in the arrays.
/// - A "point" gauge stays where it is put: the Shepard-normalised kernel average over the soil
///   within the support 2h, f(x) = Σ_j f_j W(x − x_j) V_j / Σ_j W(x − x_j) V_j with V_j = m_j/ρ_j,
///   of the particles' stress, velocity and displacement; NaN where no soil is within 2h.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "sph/geometry/vec3.h"
#include "sph/kernel.h"
#include "sph/particles.h"

namespace soilsph::sph {

enum class GaugeKind { Particle, Point };

template <int dim>
struct GaugeOf {
  using Kind = GaugeKind;
  std::string name;
  Vec<dim> position;  ///< m, at t = 0
  Kind kind = Kind::Particle;
};
using Gauge = GaugeOf<2>;

/// What a gauge reads; p and q compression-positive (p = −tr σ / 3, q = √(3 J2), full 3×3 σ), Pa.
template <int dim>
struct GaugeReadingOf {
  Vec<dim> position, displacement, velocity;
  double p, q;
};
using GaugeReading = GaugeReadingOf<2>;

template <int dim>
class GaugeSetOf {
 public:
  /// Resolves the particle gauges on the particles at t = 0 (x0, y0[, z0]); throws ParameterError
  /// naming `source` and the gauge if no soil particle lies within one spacing of a particle gauge.
  GaugeSetOf(std::vector<GaugeOf<dim>> gauges, const ParticlesOf<dim>& p, double spacing,
             const SmoothingKernel<dim>& kernel, const std::string& source);

  const std::vector<GaugeOf<dim>>& gauges() const { return gauges_; }
  bool empty() const { return gauges_.empty(); }

  /// The readings at t^n inside a step: positions and σ at t^n, velocities the mean of the
  /// particles' v^{n−½} and `v_next` (v^{n+½}).
  std::vector<GaugeReadingOf<dim>> read(const ParticlesOf<dim>& p,
                                        const std::array<std::span<const double>, dim>& v_next) const;

 private:
  std::vector<GaugeOf<dim>> gauges_;
  std::vector<std::uint64_t> particle_;  ///< the id of the followed particle of each particle gauge
  SmoothingKernel<dim> kernel_;
};
using GaugeSet = GaugeSetOf<2>;

}  // namespace soilsph::sph
