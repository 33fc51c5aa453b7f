#pragma once
/// @file
/// A wall's motion, in the plane or in space: still, removed at a time, and/or moving at a
/// constant velocity from `start` to `end` (standing still before and after). The 2D walls of a
/// layout (geometry/layout.h) and the planar walls of space (scene_3d.h, Wall3) carry one; their
/// ghosts, the ghosts' mirroring and the wall guard follow it (stages/wall_motions.h).
#include <algorithm>
#include <limits>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

template <int dim>
struct WallMotionOf {
  double removed_at = std::numeric_limits<double>::infinity();  ///< s; 0: never there (withdrawn at t = 0)
  Vec<dim> velocity{};                                          ///< m/s while it moves
  double start = 0.0, end = 0.0;                                ///< s, the moving interval

  bool moves() const { return end > start && !(velocity == Vec<dim>{}); }
  /// Removed at some time after t = 0 (a wall removed at 0 is never built).
  bool removed_during_run() const {
    return removed_at > 0.0 && removed_at < std::numeric_limits<double>::infinity();
  }
  /// Moves or goes during the run: its plane is not where it was built for the whole run.
  bool changes() const { return moves() || removed_during_run(); }
  /// Displacement from its initial position at time t.
  Vec<dim> displacement(double t) const { return displacement(0.0, t); }
  /// Displacement during [t, t + dt]: the velocity times the part of the step inside [start, end].
  Vec<dim> displacement(double t, double dt) const {
    if (!moves()) return {};
    const double moving =
        std::max(0.0, std::min(t + dt, end) - std::max(t, start));  // overlap with [start, end]
    return moving * velocity;
  }
  /// Velocity during the step [t, t + dt] (the mean over it: its displacement over dt).
  Vec<dim> velocity_during(double t, double dt) const {
    if (!moves() || dt <= 0.0) return {};
    return (1.0 / dt) * displacement(t, dt);
  }
  /// The velocity at time t: `velocity` on [start, end), 0 outside.
  Vec<dim> velocity_at(double t) const { return moves() && t >= start && t < end ? velocity : Vec<dim>{}; }
};

using WallMotion = WallMotionOf<2>;

}  // namespace soilsph::sph
