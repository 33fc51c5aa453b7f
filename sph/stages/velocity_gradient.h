#pragma once
/// @file
/// The SPH velocity gradient (paper eq 23):
///   ∂v^α/∂x^β |_i = Σ_j (m_j/ρ_j) (v_j^α − v_i^α) ∂W_ij/∂x_i^β,
/// over soil and boundary neighbours; the strain rate is its symmetric part and the spin rate
/// ω̇ = ½(∂v^α/∂x^β − ∂v^β/∂x^α) its skew part. In the plane (plane strain) the z row and column are
/// zero; in space all nine components are summed and the Jaumann rate sees all three spins.
///
/// For v = A x the sum gives A M with the kernel moment M^{γβ} = Σ_j (m_j/ρ_j)(x_j − x_i)^γ ∂W_ij/∂x_i^β,
/// which is I only for a full, regular neighbourhood: on a lattice with h = 1.3Δp it is 1.0105 I
/// (a 1 % error), and at a free surface it falls to about ½ I. The optional kernel-gradient correction
/// (Randles & Libersky 1996; Bonet & Lok 1999) multiplies by M⁻¹ so that every linear field is
/// differentiated exactly ([numerics] velocity_gradient_correction, default off: the paper's eq 23).
/// Where M is nearly singular (a nearly isolated particle: det M ≤ 0.1 in the plane; in space
/// ≤ 0.1^{3/2} ≈ 0.032, the same bound per axis) the uncorrected sum is kept. On the 3D lattice at
/// h = 1.3Δp (cubic spline) det M is 0.98 inside, 0.29 on a free face, 0.081 on an edge of two faces
/// and 0.021 at a corner of three, which keeps its uncorrected sum.
#include <array>
#include <span>

#include "constitutive/tensor.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/stages/pair_vectors.h"

namespace soilsph::sph {

/// L = ∂v^α/∂x^β of one particle, l[α][β] (l[0][1] = ∂vx/∂y).
template <int dim>
struct VelocityGradientOf {
  std::array<std::array<double, dim>, dim> l{};

  /// Strain increment ε̇Δt, ε̇ = ½(L + Lᵀ), as a 3×3 tensor (ε̇_zz = ε̇_xz = ε̇_yz = 0 in the plane).
  /// Built from scaled scalars in one initialiser rather than as a zeroed matrix set entry by entry
  /// and then scaled: GCC 12 compiled that into 8-byte stores read back by 16-byte loads, a
  /// store-forwarding stall that took 40 % of the plane's SPH stress update's own samples.
  Mat3 strain_increment(double dt) const {
    Mat3 d;
    if constexpr (dim == 2) {
      const double a = l[0][0] * dt, b = (0.5 * (l[0][1] + l[1][0])) * dt, c = l[1][1] * dt;
      d << a, b, 0.0, b, c, 0.0, 0.0, 0.0, 0.0;
    } else {
      const double xy = (0.5 * (l[0][1] + l[1][0])) * dt, xz = (0.5 * (l[0][2] + l[2][0])) * dt,
                   yz = (0.5 * (l[1][2] + l[2][1])) * dt;
      d << l[0][0] * dt, xy, xz, xy, l[1][1] * dt, yz, xz, yz, l[2][2] * dt;
    }
    return d;
  }
  /// Spin increment ω̇Δt, ω̇ = ½(L − Lᵀ) (eq 23).
  Mat3 spin_increment(double dt) const {
    Mat3 s;
    if constexpr (dim == 2) {
      const double w = (0.5 * (l[0][1] - l[1][0])) * dt;
      s << 0.0, w, 0.0, -w, 0.0, 0.0, 0.0, 0.0, 0.0;
    } else {
      const double xy = (0.5 * (l[0][1] - l[1][0])) * dt, xz = (0.5 * (l[0][2] - l[2][0])) * dt,
                   yz = (0.5 * (l[1][2] - l[2][1])) * dt;
      s << 0.0, xy, xz, -xy, 0.0, yz, -xz, -yz, 0.0;
    }
    return s;
  }
};
using VelocityGradient = VelocityGradientOf<2>;

/// Eq 23 at soil particle i and, in the same pass over its pairs, the continuity equation's
/// Dρ_i/Dt = Σ_j m_j (v_i − v_j)·∇_i W_ij (eq 11, stages/continuity.h), with the velocities v.
template <int dim>
struct KinematicRatesOf {
  VelocityGradientOf<dim> L;
  double density_rate;
};
using KinematicRates = KinematicRatesOf<2>;

/// The velocity arrays a stage reads (vx, vy[, vz]).
/// (The size is written as a conversion so that a function taking one deduces dim from its other
/// arguments: an int parameter is not deduced from std::array's size_t.)
template <int dim>
using VelocitySpans = std::array<std::span<const double>, static_cast<std::size_t>(dim)>;
/// The same, writable.
template <int dim>
using MutableVelocitySpans = std::array<std::span<double>, static_cast<std::size_t>(dim)>;

/// M⁻¹ of the kernel moment, or nothing where it is nearly singular (det M ≤ 0.1^{dim/2}, above).
template <int dim>
bool invert_moment(const std::array<std::array<double, dim>, dim>& m, std::array<std::array<double, dim>, dim>& inv) {
  if constexpr (dim == 2) {
    const double det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    if (!(det > 0.1)) return false;
    inv = {{{m[1][1] / det, -m[0][1] / det}, {-m[1][0] / det, m[0][0] / det}}};
  } else {
    Mat3 M;
    M << m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2];
    if (!(M.determinant() > 0.0316)) return false;
    const Mat3 I = M.inverse();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) inv[a][b] = I(a, b);
  }
  return true;
}

/// How eq 23 and eq 11 are summed: the scene's [numerics], chosen once per run.
struct KinematicOptions {
  bool corrected = false;          ///< eq 23 times M⁻¹ (velocity_gradient_correction, above)
  double density_diffusion = 0.0;  ///< δ h c of eq 11's diffusive term (m²/s; stages/continuity.h); 0: none
};

/// `volume_of(j)` gives m_j/ρ_j; `diffuse` whether options.density_diffusion is on, a template
/// argument so that the pair loop without it is the plain one (a runtime test per pair cost the
/// plane's paper column 2–4 % of its step, 2026-12-06).
template <bool diffuse, int dim, class Volume>
KinematicRatesOf<dim> kinematic_rates_summed(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t i,
                                             const VelocitySpans<dim>& v, Volume&& volume_of,
                                             const KinematicOptions& options) {
  VelocityGradientOf<dim> L;
  double rate = 0.0;
  std::array<std::array<double, dim>, dim> moment{};  // kernel moment M (x_j − x_i = −r)
  const bool corrected = options.corrected;
  const double diffusion = options.density_diffusion, density_i = p.density[i];
  for_each_pair_vectors(p, nl, i, [&](const PairVectors<dim>& q) {
    const std::size_t j = q.j;
    const double volume = volume_of(j);
    std::array<double, dim> dv;
    for (int a = 0; a < dim; ++a) dv[a] = v[a][j] - v[a][i];
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) L.l[a][b] += volume * dv[a] * q.g[b];
    rate -= p.mass[j] * dot(dv, q.g);
    if constexpr (diffuse)  // V_j ψ_ij·∇_i W_ij, ψ_ij = 2 (ρ_j − ρ_i)(x_j − x_i)/|x_j − x_i|², x_j − x_i = −r
      rate += diffusion * volume * 2.0 * (p.density[j] - density_i) * -dot(q.r, q.g) / dot(q.r, q.r);
    if (corrected)
      for (int a = 0; a < dim; ++a)
        for (int b = 0; b < dim; ++b) moment[a][b] -= volume * q.r[a] * q.g[b];
  });
  if (std::array<std::array<double, dim>, dim> inv; corrected && invert_moment<dim>(moment, inv)) {  // L ← L M⁻¹
    const auto l = L.l;
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) {
        double s = l[a][0] * inv[0][b];
        for (int c = 1; c < dim; ++c) s += l[a][c] * inv[c][b];
        L.l[a][b] = s;
      }
  }
  return {L, rate};
}
/// kinematic_rates_summed with the density diffusion chosen once per particle from `options`.
template <int dim, class Volume>
KinematicRatesOf<dim> kinematic_rates_with(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t i,
                                           const VelocitySpans<dim>& v, Volume&& volume_of,
                                           const KinematicOptions& options) {
  if (options.density_diffusion > 0.0) return kinematic_rates_summed<true>(p, nl, i, v, volume_of, options);
  return kinematic_rates_summed<false>(p, nl, i, v, volume_of, options);
}

/// m/ρ of particle i, read by every pair of eq 23.
template <int dim>
double particle_volume(const ParticlesOf<dim>& p, std::size_t i) {
  return p.mass[i] / p.density[i];
}

/// With `volume` holding particle_volume of every particle: one division per particle, not per pair.
template <int dim>
KinematicRatesOf<dim> kinematic_rates_of(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t i,
                                         const VelocitySpans<dim>& v, std::span<const double> volume,
                                         const KinematicOptions& options) {
  return kinematic_rates_with(p, nl, i, v, [&](std::size_t j) { return volume[j]; }, options);
}
/// The same, each volume computed where it is read.
template <int dim>
KinematicRatesOf<dim> kinematic_rates_of(const ParticlesOf<dim>& p, const PairList<dim>& nl, std::size_t i,
                                         const VelocitySpans<dim>& v, const KinematicOptions& options = {}) {
  return kinematic_rates_with(p, nl, i, v, [&](std::size_t j) { return particle_volume(p, j); }, options);
}

/// The particles' own velocities v^{n−½} as spans.
template <int dim>
VelocitySpans<dim> velocities(const ParticlesOf<dim>& p) {
  if constexpr (dim == 2)
    return {p.vx, p.vy};
  else
    return {p.vx, p.vy, p.vz};
}

/// The stored velocity-gradient arrays l[α][β] of the soil.
template <int dim>
std::array<std::array<std::vector<double>*, dim>, dim> velocity_gradient_arrays(ParticlesOf<dim>& p) {
  if constexpr (dim == 2)
    return {{{&p.lxx, &p.lxy}, {&p.lyx, &p.lyy}}};
  else
    return {{{&p.lxx, &p.lxy, &p.lxz}, {&p.lyx, &p.lyy, &p.lyz}, {&p.lzx, &p.lzy, &p.lzz}}};
}

/// Fills p.lxx, p.lxy, … for every soil particle from its velocities (orphaned OpenMP loop).
template <int dim>
void compute_velocity_gradient(ParticlesOf<dim>& p, const PairList<dim>& nl, bool corrected = false) {
  const auto n = static_cast<std::ptrdiff_t>(p.soil_count);
  const auto stored = velocity_gradient_arrays(p);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const VelocityGradientOf<dim> L = kinematic_rates_of(p, nl, i, velocities(p), {.corrected = corrected}).L;
    for (int a = 0; a < dim; ++a)
      for (int b = 0; b < dim; ++b) (*stored[a][b])[i] = L.l[a][b];
  }
}

/// The stored gradient of soil particle i (filled by compute_velocity_gradient).
template <int dim>
VelocityGradientOf<dim> stored_velocity_gradient(ParticlesOf<dim>& p, std::size_t i) {
  VelocityGradientOf<dim> L;
  const auto stored = velocity_gradient_arrays(p);
  for (int a = 0; a < dim; ++a)
    for (int b = 0; b < dim; ++b) L.l[a][b] = (*stored[a][b])[i];
  return L;
}

}  // namespace soilsph::sph
