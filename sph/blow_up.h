#pragma once
/// @file
/// Blow-up detection: cheap checks at the close of every step that stop a run whose numbers have
/// lost their meaning, instead of letting it write a deposit of particles 5 m up at 200 m/s.
/// One pass over the soil (fused with the close's own pass) checks, per particle:
///  - positions, velocities and density finite, density > 0;
///  - the speed below the P-wave speed c: a weakly compressible scheme needs |v| ≪ c, and a flow
///    faster than its elastic waves has broken it;
///  - the particle inside the domain: the floor's extent, the walls and twice the column's height
///    (a soil that runs off the floor's far end is also stopped here);
/// and over the soil:
///  - the kinetic energy below the energy the run started with (potential above the floor,
///    elastic and kinetic): the scheme dissipates, so a larger kinetic energy is created by it;
///  - the wall guard pushing back at most a few particles in one step (max(10, 1 % of the soil)):
///    more means particles cross the walls, which the ghost particles should prevent.
/// Each message names the particle and the quantity; the solver adds the step and the time.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sph/geometry/vec2.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// A run whose state lost its meaning; what() names the time, step, particle and quantity and a
/// hint at the cause.
class BlowUp : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The box no soil particle may leave (m).
struct Domain {
  double x_min = -std::numeric_limits<double>::infinity(), x_max = std::numeric_limits<double>::infinity();
  double y_min = -std::numeric_limits<double>::infinity(), y_max = std::numeric_limits<double>::infinity();
  bool contains(double x, double y) const { return x >= x_min && x <= x_max && y >= y_min && y <= y_max; }
};

/// The hint every message ends with: what usually makes an SPH step unstable.
inline constexpr const char* kBlowUpHint =
    " (a smaller [numerics] cfl, a stiffer material or more artificial viscosity usually helps; "
    "docs/method/sph.md)";

/// True if particle i's close-of-step state is sane: speed² v2 at most c², density finite and
/// positive, inside the domain. NaN fails every comparison, so a non-finite value is never sane.
inline bool particle_sane(const Particles& p, std::size_t i, double v2, double c2, const Domain& domain) {
  return v2 <= c2 && p.density[i] > 0.0 && std::isfinite(p.density[i]) && domain.contains(p.x[i], p.y[i]);
}

/// What is insane about particle i (particle_sane() is false): the message naming it.
inline std::string particle_blow_up(const Particles& p, std::size_t i, double sound_speed, const Domain& domain) {
  const double v2 = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
  const bool finite = std::isfinite(p.x[i] + p.y[i] + v2 + p.density[i]);
  const bool fast = v2 > sound_speed * sound_speed, outside = !domain.contains(p.x[i], p.y[i]);
  std::ostringstream out;
  out << "blow-up: soil particle " << i << " at (" << p.x[i] << ", " << p.y[i] << ") m";
  if (!finite)
    out << " has a non-finite position, velocity or density";
  else if (fast)
    out << " moves at " << std::sqrt(v2) << " m/s, faster than the P-wave speed c = " << sound_speed << " m/s";
  else if (outside)
    out << " left the domain x " << domain.x_min << " to " << domain.x_max << " m, y " << domain.y_min << " to "
        << domain.y_max << " m (a soil that runs past the floor's far end needs a longer [scene] floor_length)";
  else
    out << " has density " << p.density[i] << " kg/m^3";
  return out.str() + kBlowUpHint;
}

/// Where an energy blow-up shows most: "the fastest soil particle, i at (x, y) m, moves at v m/s".
inline std::string fastest_particle(const Particles& p, std::size_t i) {
  std::ostringstream out;
  out << "the fastest soil particle, " << i << " at (" << p.x[i] << ", " << p.y[i] << ") m, moves at "
      << std::hypot(p.vx[i], p.vy[i]) << " m/s";
  return out.str();
}

/// The energy a run may never exceed in kinetic energy (J per metre of thickness): the soil's
/// potential energy |g| (height − datum) along −g above the lowest wall, its elastic energy
/// ½ σ:C:σ V and its kinetic energy now; of the soil particles [begin, end), by default all.
template <class Elastic>
double energy_budget(const Particles& p, const Elastic& elasticity, Vec2 gravity, double datum, std::size_t begin = 0,
                     std::size_t end = std::numeric_limits<std::size_t>::max()) {
  end = std::min(end, p.soil_count);
  const double g = norm(gravity);
  const Vec2 down = g > 0.0 ? Vec2{gravity.x / g, gravity.y / g} : Vec2{0.0, -1.0};
  double e = 0.0;
  for (std::size_t i = begin; i < end; ++i) {
    const double volume = p.mass[i] / p.density[i];
    const Mat3& sigma = p.state[i].stress;
    const double height = -(down.x * p.x[i] + down.y * p.y[i]);
    e += p.mass[i] * (g * (height - datum) + 0.5 * (p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i])) +
         0.5 * volume * ddot(sigma, elasticity.at(mean_pressure(sigma)).compliance(sigma));
  }
  return e;
}

}  // namespace soilsph::sph
