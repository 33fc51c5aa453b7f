#pragma once
/// @file
/// Ghost (boundary) particles, paper §4.3: layers of particles behind each wall, "carrying the same
/// stress and density as the real SPH particles within the influence domain". Each step a ghost b
/// takes the kernel (Shepard) average of its soil neighbours,
///   ā_b = Σ_j a_j W_bj / Σ_j W_bj   (j soil),
/// for the stress, the density and the velocity, then mirrors it across its wall, whatever the
/// wall's direction: with n the unit normal towards the soil, t = (−n_y, n_x) the tangent, v_w the
/// wall's velocity and Δv = v̄ − v_w,
///   velocity  v_b = v̄ − 2 (Δv·n) n − 2 s (Δv·t) t
///   stress    σ_b = σ̄ + (2τ − 2σ̄_nt)(n⊗t + t⊗n),  σ̄_nt = n·σ̄·t,  τ the wall's shear traction
/// The normal relative velocity is always mirrored (the wall is impermeable and moves with v_w). The
/// wall's shear traction, the average of the soil's and the ghost's σ_nt across it, is τ:
///  - free slip, μ = 0: τ = 0, the shear stress and the tangential velocity are mirrored and copied
///    (σ_b,nt = −σ̄_nt, s = 0): no shear traction;
///  - no slip, μ = +∞: τ = σ̄_nt, the stress copied and the velocity 2 v_w − v̄ (s = 1; Adami et al.
///    2012, J. Comput. Phys. 231:7057), so the velocity interpolates to v_w at the wall;
///  - frictional, μ = tan δ: Coulomb's law on the wall, |τ| ≤ μ σ'_n with σ'_n = −σ̄_nn the normal
///    compression the soil puts on it, decided from the slip Δv_t = (v̄ − v_w)·t (v̄ the kernel
///    average of the soil velocity v^n, taken with the stress). While the soil slips along the wall
///    (|Δv_t| > kStickSlip) it slides with kinetic friction against the slip: τ = μ σ'_n sign(Δv_t),
///    the tangential velocity copied as on a free-slip wall (s = 0), whatever shear the soil has
///    built (a sliding soil barely builds any, so a friction read from σ̄_nt would transmit only
///    about a quarter of μσ'_n). At (nearly) no slip it sticks as no slip
///    (τ = σ̄_nt, s = 1) while the demanded shear is within the limit (|σ̄_nt| < μ σ'_n), and starts
///    to slide, τ = ±μ σ'_n with the sign of σ̄_nt, beyond it. A wall in tension (σ̄_nn ≥ 0) holds
///    no shear.
///    Sign: the momentum equation Σ_j m_j (σ_i/ρ_i² + σ_j/ρ_j²)·∇_i W_ij over the ghosts j behind
///    the wall (x_i − x_j along +n, so ∇_i W_ij = W' (x_i − x_j)/r along −n, W' < 0) gives soil i
///    the tangential force
///    ∝ −(σ_i,nt + σ_j,nt), i.e. the traction σ·(−n) of a continuum with outward normal −n: the
///    wall pushes the soil by −τ t. Friction opposing a slip along +t therefore needs τ > 0, the
///    sign of Δv_t (as in the no-slip case: soil moving along +t over a stuck wall has
///    ∂v_t/∂n > 0, so σ_nt = 2G ε_nt > 0, which brakes it). Measured (block_on_incline, 1 mm,
///    0.05 s): the block with δ = 15° on the 30° incline reached 0.078 m/s down the
///    slope (free slip 0.211, Coulomb g(sin θ − tan δ cos θ) t = 0.131; a switch reading σ̄_nt:
///    0.178): friction took 0.133 m/s off the free-slip block, 1.17 of Coulomb's μ g cos θ t
///    (1.12 without the ghosts' weight below; a flat wall with gravity tilted by 30°: 1.20),
///    so the wall transmits slightly more than μσ'_n; why is open (docs/reference/scenes.md). δ = 45°
///    still holds it.
/// The soil's weight continues across the wall ([numerics] ghost_body_force, default on): each soil
/// neighbour's normal stress is carried to the ghost along n by the normal equilibrium
/// ∂σ_nn/∂n = −ρ b·n (b the body force per mass, gravity; the wall at rest or moving steadily), so
///   σ_b += Δ n⊗n,  Δ = (b·n) Σ_j W_bj ρ_j n·(x_j − x_b) / Σ_j W_bj,
/// the stress counterpart of Adami et al.'s (2012) hydrostatic ghost pressure (their eq 27), along the
/// normal only: σ_tt and σ_nt have no equilibrium that fixes their normal gradient. For the geostatic
/// column (uniform ρ, σ_yy = −ρg(y_top − y)) a floor ghost then carries exactly the geostatic σ_yy of
/// its own depth; without it the ghost has the soil's average, 3 % less compression at 2 mm, and
/// the bottom row starts falling at 0.51 g (tests/sph/test_boundaries.cpp). Δ leaves σ_nt, hence
/// the friction, unchanged. The wall guard of soil flowing over a floor at h/Δp = 3.2 halves with it
/// (docs/method/sph.md), the shipped scenes never need the guard either way.
/// The stick flag s is decided with the stress (loop 1 of the step) and used for the velocity (loop 3).
/// For axis-aligned walls with v_w = 0 these are the column's former formulas, operation for
/// operation: (σxx, σyy, −σxy) and (−v̄x, v̄y) on a vertical free-slip wall, σ̄ and −v̄ on the no-slip
/// floor (the multiplications by 0 and ±1 are exact). A ghost with no soil neighbour keeps zero stress
/// and velocity and its density.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <vector>

#include "sph/geometry/layout.h"
#include "sph/geometry/wall_mirror.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/guard_pushes.h"
#include "sph/stages/pair_vectors.h"
#include "sph/stages/velocity_gradient.h"
#include "sph/stages/wall_motions.h"

namespace soilsph::sph {

/// The slip speed along a frictional wall (m/s) below which the soil may stick (see above).
inline constexpr double kStickSlip = 1e-4;

/// The kernel (Shepard) averages of ghost b's soil neighbours: Σ_j W_bj and the W-weighted sums of
/// the stress (symmetric_index order), ρ, v and ρ (x_b − x_j).
template <int dim>
struct ShepardSums {
  double weight = 0.0, density = 0.0;
  std::array<double, kSymmetricComponents<dim>> stress{};
  std::array<double, dim> velocity{}, density_offset{};
};
template <int dim>
ShepardSums<dim> shepard_sums(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t b) {
  ShepardSums<dim> sums;
  const auto stress = stress_arrays(p);
  const auto velocity = velocities(p);
  for_each_pair_vectors(p, nl, b, [&](const PairVectors<dim>& q) {  // soil: no boundary–boundary pairs
    sums.weight += q.w;
    for (int a = 0; a < dim; ++a) sums.density_offset[a] += q.w * p.density[q.j] * q.r[a];
    for (int k = 0; k < kSymmetricComponents<dim>; ++k) sums.stress[k] += q.w * (*stress[k])[q.j];
    sums.density += q.w * p.density[q.j];
    for (int a = 0; a < dim; ++a) sums.velocity[a] += q.w * velocity[a][q.j];
  });
  return sums;
}

/// Sets ghost b's stress, density and stick flag from the soil (σ^n, ρ^n, before the momentum
/// equation), the normal stress balancing the body force per mass `body` (see above). In space the
/// mirror is geometry/wall_mirror.h's, the same rules with the tangential traction and slip as vectors.
template <int dim>
void mirror_stress_onto_ghost(ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t b, Vec<dim> body = {}) {
  const ShepardSums<dim> sums = shepard_sums(p, nl, b);
  const double sum_w = sums.weight;
  const auto stress = stress_arrays(p);
  if (sum_w <= 0.0) {
    for (auto* s : stress) (*s)[b] = 0.0;
    return;
  }
  const std::size_t g = b - p.soil_count;
  const double mu = p.wall_friction[g];
  if constexpr (dim == 2) {
    const double nx = p.wall_nx[g], ny = p.wall_ny[g], tx = -ny, ty = nx;
    const double sxx = sums.stress[0] / sum_w, syy = sums.stress[1] / sum_w, sxy = sums.stress[2] / sum_w;
    const double s_nn = nx * (sxx * nx + sxy * ny) + ny * (sxy * nx + syy * ny);
    const double s_nt = nx * (sxx * tx + sxy * ty) + ny * (sxy * tx + syy * ty);
    const double limit = mu < std::numeric_limits<double>::infinity() ? mu * std::max(-s_nn, 0.0)
                                                                      : std::numeric_limits<double>::infinity();
    double tau = std::clamp(s_nt, -limit, limit);
    double stick = std::abs(s_nt) < limit ? 1.0 : 0.0;
    if (limit > 0.0 && limit < std::numeric_limits<double>::infinity()) {  // frictional (and compressed)
      // Kinetic Coulomb friction: while the soil slips along the wall the traction is the limit
      // against the slip (τ has the sign of Δv_t, see above), whatever shear the soil has built.
      const double slip =
          (sums.velocity[0] / sum_w - p.wall_vx[g]) * tx + (sums.velocity[1] / sum_w - p.wall_vy[g]) * ty;
      if (std::abs(slip) > kStickSlip) tau = std::copysign(limit, slip), stick = 0.0;
    }
    const double change = (2.0 * tau - s_nt) - s_nt;  // σ_b,nt − σ̄_nt
    p.wall_stick[g] = stick;
    p.sxx[b] = sxx + change * (2.0 * nx * tx);
    p.syy[b] = syy + change * (2.0 * ny * ty);
    p.sxy[b] = sxy + change * (nx * ty + tx * ny);
    const double delta =
        -(body.x * nx + body.y * ny) * (sums.density_offset[0] * nx + sums.density_offset[1] * ny) / sum_w;  // Δ
    p.sxx[b] += delta * nx * nx;
    p.syy[b] += delta * ny * ny;
    p.sxy[b] += delta * nx * ny;
  } else {
    const Vec3 n{p.wall_nx[g], p.wall_ny[g], p.wall_nz[g]};
    Eigen::Matrix3d mean;
    const double xx = sums.stress[0] / sum_w, yy = sums.stress[1] / sum_w, zz = sums.stress[2] / sum_w,
                 xy = sums.stress[3] / sum_w, xz = sums.stress[4] / sum_w, yz = sums.stress[5] / sum_w;
    mean << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    const Vec3 relative{sums.velocity[0] / sum_w - p.wall_vx[g], sums.velocity[1] / sum_w - p.wall_vy[g],
                        sums.velocity[2] / sum_w - p.wall_vz[g]};
    const WallShear shear = wall_shear(mean, n, relative, mu, kStickSlip);
    p.wall_stick[g] = shear.stick;
    const Vec3 offset{sums.density_offset[0], sums.density_offset[1], sums.density_offset[2]};
    const double delta = -dot(body, n) * dot(offset, n) / sum_w;  // Δ above
    const Eigen::Vector3d nn{n.x, n.y, n.z};
    Eigen::Matrix3d ghost = ghost_stress(mean, n, shear.traction) + delta * nn * nn.transpose();
    // The image across the further free-slip walls the ghost lies behind: σ_ab s_a s_b.
    const Eigen::Vector3d sign{p.image_sign_x[g], p.image_sign_y[g], p.image_sign_z[g]};
    ghost = ghost.cwiseProduct(sign * sign.transpose());
    p.sxx[b] = ghost(0, 0), p.syy[b] = ghost(1, 1), p.szz[b] = ghost(2, 2);
    p.sxy[b] = ghost(0, 1), p.sxz[b] = ghost(0, 2), p.syz[b] = ghost(1, 2);
  }
  p.density[b] = sums.density / sum_w;
}

/// Sets ghost b's velocity in v from the soil velocities in the same arrays (for the viscosity, the
/// velocity gradient and eq 11).
template <int dim>
void mirror_velocity_onto_ghost(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t b,
                                const MutableVelocitySpans<dim>& v) {
  double sum_w = 0.0;
  std::array<double, dim> sum{};
  nl.for_each_pair(b, [&](const typename PairList<dim>::Pair& q) {
    sum_w += q.w;
    for (int a = 0; a < dim; ++a) sum[a] += q.w * v[a][q.j];
  });
  if (sum_w <= 0.0) {
    for (int a = 0; a < dim; ++a) v[a][b] = 0.0;
    return;
  }
  const std::size_t g = b - p.soil_count;
  const double s = p.wall_stick[g];
  if constexpr (dim == 2) {
    const double nx = p.wall_nx[g], ny = p.wall_ny[g], tx = -ny, ty = nx;
    const double v_x = sum[0] / sum_w, v_y = sum[1] / sum_w;
    const double dvx = v_x - p.wall_vx[g], dvy = v_y - p.wall_vy[g];
    const double dn = dvx * nx + dvy * ny, dt = dvx * tx + dvy * ty;
    v[0][b] = v_x - 2.0 * dn * nx - 2.0 * s * dt * tx;
    v[1][b] = v_y - 2.0 * dn * ny - 2.0 * s * dt * ty;
  } else {
    const Vec3 ghost = ghost_velocity({sum[0] / sum_w, sum[1] / sum_w, sum[2] / sum_w},
                                {p.wall_vx[g], p.wall_vy[g], p.wall_vz[g]}, {p.wall_nx[g], p.wall_ny[g], p.wall_nz[g]},
                                s);
    // The image across the further free-slip walls the ghost lies behind: v_a s_a.
    v[0][b] = p.image_sign_x[g] * ghost.x, v[1][b] = p.image_sign_y[g] * ghost.y, v[2][b] = p.image_sign_z[g] * ghost.z;
  }
}

/// The friction coefficient μ a ghost of this wall mirrors with (see above).
inline double wall_friction_coefficient(const Wall& wall) {
  switch (wall.kind) {
    case WallKind::FreeSlip: return 0.0;
    case WallKind::NoSlip: return std::numeric_limits<double>::infinity();
    case WallKind::Frictional: break;
  }
  return std::tan(wall.friction_angle * std::numbers::pi / 180.0);
}

/// The last line of defence: a soil particle found behind a wall surface (within the wall's ghost
/// layers, along its length) is put back on it and its velocity into the wall, relative to the wall,
/// removed. With the ghost particles' stress and the viscosity this should never act; the solver
/// counts how often it does and reports it.
struct WallGuard {
  /// One straight piece of a wall surface.
  struct Face {
    Vec2 a, b;         ///< end points at t = 0, the soil on the left from a to b
    double depth;      ///< how far behind the surface (and beyond its ends) the guard reaches (m)
    WallMotion motion;
  };
  std::vector<Face> faces;

  /// The particles corrected at time t (one put back on the surface may lie an ulp behind it: that
  /// is not beyond).
  GuardPushes apply(Particles& p, double t) const {
    GuardPushes pushed;
    for (const Face& f : faces) {
      if (t >= f.motion.removed_at) continue;
      const Vec2 shift = f.motion.displacement(t), a = f.a + shift;
      const Vec2 along = f.b - f.a;
      const double length = norm(along);
      const Vec2 tangent = (1.0 / length) * along, n{-tangent.y, tangent.x};
      const bool moving = f.motion.moves() && t >= f.motion.start && t < f.motion.end;
      const Vec2 vw = moving ? f.motion.velocity : Vec2{};
      const double c = dot(a, n), behind = -1e-12 * f.depth;  // d = x·n − a·n: one product pair per particle
      for (std::size_t i = 0; i < p.soil_count; ++i) {
        const double d = p.x[i] * n.x + p.y[i] * n.y - c;
        if (!(d < behind)) continue;  // in front of the wall: nearly every particle, every step
        const double s = (p.x[i] - a.x) * tangent.x + (p.y[i] - a.y) * tangent.y;
        if (d < -f.depth || s < -f.depth || s > length + f.depth) continue;
        p.x[i] -= d * n.x, p.y[i] -= d * n.y;
        const double vn = (p.vx[i] - vw.x) * n.x + (p.vy[i] - vw.y) * n.y;
        if (vn < 0.0) p.vx[i] -= vn * n.x, p.vy[i] -= vn * n.y;
        ++pushed.count;
        if (s < 0.0 || s > length) ++pushed.past_edge;
      }
    }
    return pushed;
  }
};

}  // namespace soilsph::sph
