#pragma once
/// @file
/// The wall guard of space (the plane's is WallGuard, stages/boundaries.h): the last line of
/// defence that puts a soil particle found behind a planar wall — within its ghost layers, and
/// over the wall's outline grown by as much — back on the wall's plane, and removes its velocity
/// into the wall relative to the wall. With the ghosts' stress and the viscosity it should never
/// act; the solver counts how often it does. A moving wall's face is guarded where the wall is at
/// the time (its plane and outline shifted by the motion's displacement), a removed one no longer.
#include <algorithm>
#include <vector>

#include "sph/geometry/planar_wall.h"
#include "sph/geometry/polygon.h"
#include "sph/geometry/wall_motion.h"
#include "sph/particles.h"
#include "sph/stages/guard_pushes.h"

namespace soilsph::sph {

struct PlaneGuard {
  struct Face {
    PlanarWall wall;
    double depth;  ///< how far behind the plane (and beyond the outline) the guard reaches (m)
    Vec2 outline_lo, outline_hi;  ///< the outline's bounds in the plane's (u, v)
    WallMotionOf<3> motion;       ///< the wall's (still by default)
  };
  std::vector<Face> faces;

  /// Guards `wall` to `depth` behind it, where `motion` takes it.
  void add(const PlanarWall& wall, double depth, const WallMotionOf<3>& motion = {}) {
    Vec2 lo = wall.outline.front(), hi = lo;
    for (const Vec2& q : wall.outline)
      lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)}, hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
    faces.push_back({wall, depth, lo, hi, motion});
  }

  /// The particles corrected at time t.
  GuardPushes apply(ParticlesOf<3>& p, double t) const {
    GuardPushes pushed;
    for (const Face& f : faces) {
      if (t >= f.motion.removed_at) continue;
      const Vec3 n = f.wall.inward, shift = f.motion.displacement(t), vw = f.motion.velocity_at(t);
      const double c = dot(f.wall.origin + shift, n), behind = -1e-12 * f.depth;
      for (std::size_t i = 0; i < p.soil_count; ++i) {
        const double d = p.x[i] * n.x + p.y[i] * n.y + p.z[i] * n.z - c;
        if (!(d < behind)) continue;  // in front of the wall: nearly every particle, every step
        if (d < -f.depth) continue;
        const Vec2 q = f.wall.in_plane(p.position(i) - shift);
        if (q.x < f.outline_lo.x - f.depth || q.x > f.outline_hi.x + f.depth || q.y < f.outline_lo.y - f.depth ||
            q.y > f.outline_hi.y + f.depth)
          continue;
        p.x[i] -= d * n.x, p.y[i] -= d * n.y, p.z[i] -= d * n.z;
        const double vn = (p.vx[i] - vw.x) * n.x + (p.vy[i] - vw.y) * n.y + (p.vz[i] - vw.z) * n.z;
        if (vn < 0.0) p.vx[i] -= vn * n.x, p.vy[i] -= vn * n.y, p.vz[i] -= vn * n.z;
        ++pushed.count;
        if (!inside_or_on(f.wall.outline, q, 0.0)) ++pushed.past_edge;
      }
    }
    return pushed;
  }
};

}  // namespace soilsph::sph
