#pragma once
/// @file
/// The walls that move or go during a run, in the plane and in space: their ghosts move with them
/// (the same displacement as the wall over each step, so the ghosts sweep through the soil rather
/// than jump) and carry the wall's velocity v_w into the mirroring (stages/boundaries.h); a removed
/// wall's ghosts lose their mass, so no pair feels them any more.
#include <cstddef>
#include <vector>

#include "sph/geometry/wall_motion.h"
#include "sph/particles.h"

namespace soilsph::sph {

template <int dim>
struct WallMotionsOf {
  std::vector<WallMotionOf<dim>> motions;  ///< by wall index (ParticlesOf::wall_id)
  bool any = false;                        ///< some wall moves or is removed after t = 0

  /// Records the motion of the next wall.
  void add(const WallMotionOf<dim>& motion) {
    motions.push_back(motion);
    any = any || motion.changes();
  }

  /// Moves the ghosts over [t, t + dt] and sets their wall velocity and mass for time t + dt (serial).
  void advance(ParticlesOf<dim>& p, double t, double dt) const {
    if (!any) return;
    for (std::size_t g = 0; g < p.boundary_count(); ++g) {
      const WallMotionOf<dim>& m = motions[static_cast<std::size_t>(p.wall_id[g])];
      const std::size_t b = p.soil_count + g;
      const Vec<dim> d = m.displacement(t, dt);
      p.x[b] += d.x, p.y[b] += d.y;
      if constexpr (dim == 3) p.z[b] += d.z;
      if (t + dt >= m.removed_at) p.mass[b] = 0.0;
    }
    set_velocities(p, t + dt);
  }

  /// The wall velocity of every ghost at time t (the velocity of the motion it is in, if any).
  void set_velocities(ParticlesOf<dim>& p, double t) const {
    if (!any) return;
    for (std::size_t g = 0; g < p.boundary_count(); ++g) {
      const Vec<dim> v = motions[static_cast<std::size_t>(p.wall_id[g])].velocity_at(t);
      p.wall_vx[g] = v.x, p.wall_vy[g] = v.y;
      if constexpr (dim == 3) p.wall_vz[g] = v.z;
    }
  }
};

using WallMotions = WallMotionsOf<2>;

}  // namespace soilsph::sph
