#pragma once
/// @file
/// Gauges: points of a scene where p, q, velocity and displacement are sampled over time
/// ([[gauges]], docs/reference/scenes.md; written to gauges.csv, docs/reference/output-formats.md).
/// - A "particle" gauge is a material point: the soil particle nearest its position at t = 0, which
///   it follows (its displacement is that particle's).
/// - A "point" gauge stays where it is put: the Shepard-normalised kernel average over the soil
///   within the support 2h, f(x) = Σ_j f_j W(x − x_j) V_j / Σ_j W(x − x_j) V_j with V_j = m_j/ρ_j,
///   of the particles' stress, velocity and displacement; NaN where no soil is within 2h.
#include <span>
#include <string>
#include <vector>

#include "sph/geometry/vec2.h"
#include "sph/kernel.h"
#include "sph/particles.h"

namespace soilsph::sph {

struct Gauge {
  enum class Kind { Particle, Point };
  std::string name;
  Vec2 position;  ///< m, at t = 0
  Kind kind = Kind::Particle;
};

/// What a gauge reads; p and q compression-positive (p = −tr σ / 3, q = √(3 J2), full 3×3 σ), Pa.
struct GaugeReading {
  Vec2 position, displacement, velocity;
  double p, q;
};

class GaugeSet {
 public:
  /// Resolves the particle gauges on the particles at t = 0 (x0, y0); throws ParameterError naming
  /// `source` and the gauge if no soil particle lies within one spacing of a particle gauge.
  GaugeSet(std::vector<Gauge> gauges, const Particles& p, double spacing, const CubicSpline& kernel,
           const std::string& source);

  const std::vector<Gauge>& gauges() const { return gauges_; }
  bool empty() const { return gauges_.empty(); }

  /// The readings at t^n inside a step: positions and σ at t^n, velocities the mean of p.vx, p.vy
  /// (v^{n−½}) and vx_next, vy_next (v^{n+½}).
  std::vector<GaugeReading> read(const Particles& p, std::span<const double> vx_next,
                                 std::span<const double> vy_next) const;

 private:
  std::vector<Gauge> gauges_;
  std::vector<std::size_t> particle_;  ///< the followed particle of each particle gauge
  CubicSpline kernel_;
};

}  // namespace soilsph::sph
