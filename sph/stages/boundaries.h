#pragma once
/// @file
/// Fixed ghost (boundary) particles, paper §4.3: layers of particles on a lattice behind each wall,
/// "carrying the same stress and density as the real SPH particles within the influence domain".
/// Each step a boundary particle b takes the kernel (Shepard) average of its soil neighbours,
///   ā_b = Σ_j a_j W_bj / Σ_j W_bj   (j soil),
/// for the stress, the density and the velocity, then mirrors it according to the wall:
///  - vertical walls, free slip: stress (σxx, σyy, −σxy) and velocity (−v̄x, v̄y). The mirrored shear
///    cancels the soil's shear across the wall and the mirrored normal velocity makes the wall
///    impermeable, while the tangential velocity is copied: no shear traction, free slip.
///  - the floor, no slip: stress copied, velocity −v̄ (the wall velocity 2·0 − v̄ of Adami et al. 2012,
///    J. Comput. Phys. 231:7057), so the velocity interpolates to zero at the wall: no slip.
/// A boundary particle with no soil neighbour keeps zero stress and velocity and its density.
#include <algorithm>
#include <optional>
#include <span>

#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

/// Sets ghost b's stress and density from the soil (σ^n, ρ^n, before the momentum equation).
inline void mirror_stress_onto_ghost(Particles& p, const NeighbourList& nl, std::size_t b) {
  double sum_w = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0, rho = 0.0;
  nl.for_each_pair(b, [&](const NeighbourList::Pair& q) {  // soil: no boundary–boundary pairs
    sum_w += q.w;
    sxx += q.w * p.sxx[q.j];
    syy += q.w * p.syy[q.j];
    sxy += q.w * p.sxy[q.j];
    rho += q.w * p.density[q.j];
  });
  if (sum_w <= 0.0) {
    p.sxx[b] = p.syy[b] = p.sxy[b] = 0.0;
    return;
  }
  const double mirror = p.boundary_kind[b - p.soil_count] == BoundaryKind::FreeSlipWall ? -1.0 : 1.0;
  p.sxx[b] = sxx / sum_w;
  p.syy[b] = syy / sum_w;
  p.sxy[b] = mirror * sxy / sum_w;
  p.density[b] = rho / sum_w;
}

/// Sets ghost b's velocity in (vx, vy) from the soil velocities in the same arrays (for the
/// viscosity, the velocity gradient and eq 11).
inline void mirror_velocity_onto_ghost(const Particles& p, const NeighbourList& nl, std::size_t b,
                                       std::span<double> vx, std::span<double> vy) {
  double sum_w = 0.0, vx_sum = 0.0, vy_sum = 0.0;
  nl.for_each_pair(b, [&](const NeighbourList::Pair& q) {
    sum_w += q.w;
    vx_sum += q.w * vx[q.j];
    vy_sum += q.w * vy[q.j];
  });
  if (sum_w <= 0.0) {
    vx[b] = vy[b] = 0.0;
    return;
  }
  const double tangential = p.boundary_kind[b - p.soil_count] == BoundaryKind::FreeSlipWall ? 1.0 : -1.0;
  vx[b] = -vx_sum / sum_w;
  vy[b] = tangential * vy_sum / sum_w;
}

/// Every ghost's stress and density (orphaned OpenMP loop).
inline void mirror_stress_onto_boundary(Particles& p, const NeighbourList& nl) {
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = static_cast<std::ptrdiff_t>(p.soil_count); s < n; ++s)
    mirror_stress_onto_ghost(p, nl, static_cast<std::size_t>(s));
}

/// Every ghost's velocity in p.vx, p.vy (orphaned OpenMP loop).
inline void mirror_velocity_onto_boundary(Particles& p, const NeighbourList& nl) {
  const auto n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = static_cast<std::ptrdiff_t>(p.soil_count); s < n; ++s)
    mirror_velocity_onto_ghost(p, nl, static_cast<std::size_t>(s), p.vx, p.vy);
}

/// The last line of defence: the wall surfaces lie half a spacing in front of the first boundary
/// layer; a soil particle found beyond one is put back on it and its normal velocity into the wall
/// is removed. With the ghost particles' stress and the viscosity this should never act; the
/// solver counts how often it does and reports it.
struct WallGuard {
  double floor_y;                     ///< floor surface (m)
  double right_wall_x;                ///< fixed wall surface (m)
  std::optional<double> left_wall_x;  ///< removable wall surface, if the wall is there

  /// Returns the number of particles corrected.
  std::size_t apply(Particles& p) const {
    std::size_t corrected = 0;
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      bool hit = false;
      if (p.y[i] < floor_y) {
        p.y[i] = floor_y, p.vy[i] = std::max(p.vy[i], 0.0), hit = true;
      }
      if (p.x[i] > right_wall_x) {
        p.x[i] = right_wall_x, p.vx[i] = std::min(p.vx[i], 0.0), hit = true;
      }
      if (left_wall_x && p.x[i] < *left_wall_x) {
        p.x[i] = *left_wall_x, p.vx[i] = std::max(p.vx[i], 0.0), hit = true;
      }
      corrected += hit;
    }
    return corrected;
  }
};

}  // namespace soilsph::sph
