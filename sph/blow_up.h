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

#include "sph/geometry/vec3.h"
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
  bool contains(Vec2 p) const { return contains(p.x, p.y); }
};
/// The domain of a dimension: the plane's Domain, space's box.
template <int dim>
using DomainOf = std::conditional_t<dim == 2, Domain, Box3>;

/// "(x, y) m" or "(x, y, z) m".
template <int dim>
std::string position_text(const ParticlesOf<dim>& p, std::size_t i) {
  std::ostringstream out;
  const Vec<dim> x = p.position(i);
  out << "(" << x.x << ", " << x.y;
  if constexpr (dim == 3) out << ", " << x.z;
  out << ") m";
  return out.str();
}
/// "x min to max m, y …[, z …]".
inline std::string domain_text(const Domain& d) {
  std::ostringstream out;
  out << "x " << d.x_min << " to " << d.x_max << " m, y " << d.y_min << " to " << d.y_max << " m";
  return out.str();
}
inline std::string domain_text(const Box3& d) {
  std::ostringstream out;
  out << "x " << d.lo.x << " to " << d.hi.x << " m, y " << d.lo.y << " to " << d.hi.y << " m, z " << d.lo.z << " to "
      << d.hi.z << " m";
  return out.str();
}

/// The hint every message ends with: what usually makes an SPH step unstable.
inline constexpr const char* kBlowUpHint =
    " (a smaller [numerics] cfl, a stiffer material or more artificial viscosity usually helps; "
    "docs/method/sph.md)";

/// The keys that lengthen the floor a particle ran off: the 2D column's, and in 3D each shape's.
template <int dim>
inline constexpr const char* kLongerFloorHint =
    dim == 2 ? " (a soil that runs past the floor's far end needs a longer [scene] floor_length)"
             : " (a soil that runs past the floor's far end needs a longer floor: [scene] floor_radius for "
               "the axisymmetric column, floor_length for the slab, floor_margin for regions)";

/// True if particle i's close-of-step state is sane: speed² v2 at most c², density finite and
/// positive, inside the domain. NaN fails every comparison, so a non-finite value is never sane.
template <int dim>
bool particle_sane(const ParticlesOf<dim>& p, std::size_t i, double v2, double c2, const DomainOf<dim>& domain) {
  return v2 <= c2 && p.density[i] > 0.0 && std::isfinite(p.density[i]) && domain.contains(p.position(i));
}

/// What is insane about particle i (particle_sane() is false): the message naming it.
template <int dim>
std::string particle_blow_up(const ParticlesOf<dim>& p, std::size_t i, double sound_speed, const DomainOf<dim>& domain) {
  const Vec<dim> x = p.position(i), v = p.velocity(i);
  const double v2 = dot(v, v);
  const bool finite = std::isfinite(dot(x, x) + v2 + p.density[i]);
  const bool fast = v2 > sound_speed * sound_speed, outside = !domain.contains(x);
  std::ostringstream out;
  out << "blow-up: soil particle " << p.id[i] << " at " << position_text(p, i);
  if (!finite)
    out << " has a non-finite position, velocity or density";
  else if (fast)
    out << " moves at " << std::sqrt(v2) << " m/s, faster than the P-wave speed c = " << sound_speed << " m/s";
  else if (outside)
    out << " left the domain " << domain_text(domain) << kLongerFloorHint<dim>;
  else
    out << " has density " << p.density[i] << " kg/m^3";
  return out.str() + kBlowUpHint;
}

/// Where an energy blow-up shows most: "the fastest soil particle, i at (x, y) m, moves at v m/s".
template <int dim>
std::string fastest_particle(const ParticlesOf<dim>& p, std::size_t i) {
  std::ostringstream out;
  out << "the fastest soil particle, " << i << " at " << position_text(p, i) << ", moves at " << norm(p.velocity(i))
      << " m/s";
  return out.str();
}

/// The energy a run may never exceed in kinetic energy (J; per metre of thickness in the plane): the soil's
/// potential energy |g| (height − datum) along −g above the lowest wall, its elastic energy
/// ½ σ:C:σ V and its kinetic energy now; of the soil particles [begin, end), by default all.
template <int dim, class Elastic>
double energy_budget(const ParticlesOf<dim>& p, const Elastic& elasticity, Vec<dim> gravity, double datum,
                     std::size_t begin = 0, std::size_t end = std::numeric_limits<std::size_t>::max()) {
  end = std::min(end, p.soil_count);
  const double g = norm(gravity);
  Vec<dim> down{};
  down.y = -1.0;
  if (g > 0.0) {
    down.x = gravity.x / g, down.y = gravity.y / g;
    if constexpr (dim == 3) down.z = gravity.z / g;
  }
  double e = 0.0;
  for (std::size_t i = begin; i < end; ++i) {
    const double volume = p.mass[i] / p.density[i];
    const Mat3& sigma = p.state[i].stress;
    const double height = -dot(down, p.position(i));
    const Vec<dim> v = p.velocity(i);
    e += p.mass[i] * (g * (height - datum) + 0.5 * dot(v, v)) +
         0.5 * volume * ddot(sigma, elasticity.at(mean_pressure(sigma)).compliance(sigma));
  }
  return e;
}

}  // namespace soilsph::sph
