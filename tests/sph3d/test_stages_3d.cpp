// The SPH stages in space against closed forms: eq 23 on a linear velocity field, eq 12 on uniform
// and linear stress fields, the artificial stress of a tensile principal stress along an oblique
// axis, and the mirror of a ghost behind a plane.
#include <catch2/catch.hpp>

#include <cmath>

#include "sph/neighbours/neighbour_list.h"
#include "sph/stages/artificial_stress.h"
#include "sph/stages/boundaries.h"
#include "sph/stages/momentum.h"
#include "sph/stages/velocity_gradient.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
constexpr double kDensity = 2000.0;

/// An n × n × n cube of soil particles of spacing dx from the origin, at rest.
ParticlesOf<3> cube(int n, double dx) {
  ParticlesOf<3> p;
  p.resize(static_cast<std::size_t>(n * n * n), 0);
  std::size_t i = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l, ++i) {
        p.x[i] = l * dx, p.y[i] = j * dx, p.z[i] = k * dx;
        p.density[i] = kDensity;
        p.mass[i] = kDensity * dx * dx * dx;
      }
  return p;
}
std::size_t centre_of(int n) { return static_cast<std::size_t>((n / 2 * n + n / 2) * n + n / 2); }

/// The lattice moment Σ_j V (x_j − x_i)_x ∂W/∂x_i for a full neighbourhood, from the kernel formula.
double lattice_moment(const CubicSplineKernel<3>& W, double dx) {
  double m = 0.0;
  for (int a = -3; a <= 3; ++a)
    for (int b = -3; b <= 3; ++b)
      for (int c = -3; c <= 3; ++c) {
        const double xj = a * dx, r = dx * std::sqrt(a * a + b * b + c * c);
        if (r > 0.0) m += dx * dx * dx * xj * W.derivative(r) * (-xj) / r;
      }
  return m;
}

constexpr double A[3][3] = {{0.7, -1.3, 0.4}, {2.1, -0.4, -0.9}, {-0.6, 1.5, 0.2}};
}  // namespace

TEST_CASE("eq 23 in space: the linear field's gradient times the lattice moment, exact when corrected",
          "[stages-3d]") {
  const double dx = 1e-3;
  const int n = 9;
  const CubicSplineKernel<3> W(1.3 * dx);
  ParticlesOf<3> p = cube(n, dx);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x[3] = {p.x[i], p.y[i], p.z[i]};
    double* v[3] = {&p.vx[i], &p.vy[i], &p.vz[i]};
    for (int a = 0; a < 3; ++a) *v[a] = 0.1 * a + A[a][0] * x[0] + A[a][1] * x[1] + A[a][2] * x[2];
  }
  PairList<3> nl;
  nl.build(p.coordinates(), W, p.size());
  const std::size_t c = centre_of(n);
  const double m = lattice_moment(W, dx);
  CHECK(m == Approx(1.0).epsilon(0.03));
  const VelocityGradientOf<3> plain = kinematic_rates_of(p, nl, c, velocities(p)).L;
  const VelocityGradientOf<3> corrected = kinematic_rates_of(p, nl, c, velocities(p), {.corrected = true}).L;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      CHECK(plain.l[a][b] == Approx(A[a][b] * m).epsilon(1e-9));
      CHECK(corrected.l[a][b] == Approx(A[a][b]).epsilon(1e-9));
    }
  // A particle on a face (z = 0), half its neighbourhood missing: still exact when corrected.
  const std::size_t face = static_cast<std::size_t>(n / 2 * n + n / 2);
  const VelocityGradientOf<3> on_face = kinematic_rates_of(p, nl, face, velocities(p), {.corrected = true}).L;
  CHECK(kinematic_rates_of(p, nl, face, velocities(p)).L.l[2][1] != Approx(A[2][1]).epsilon(0.1));
  CHECK(on_face.l[2][1] == Approx(A[2][1]).epsilon(1e-9));
  CHECK(on_face.l[0][2] == Approx(A[0][2]).epsilon(1e-9));
  // ε̇ and ω̇ split L into its symmetric and skew parts, with every off-diagonal pair.
  const double dt = 1e-3;
  const Mat3 strain = corrected.strain_increment(dt), spin = corrected.spin_increment(dt);
  CHECK(strain(0, 2) == Approx(0.5 * (A[0][2] + A[2][0]) * dt));
  CHECK(strain(2, 2) == Approx(A[2][2] * dt));
  CHECK(spin(1, 2) == Approx(0.5 * (A[1][2] - A[2][1]) * dt));
  CHECK(spin(2, 1) == Approx(-0.5 * (A[1][2] - A[2][1]) * dt));
  // The divergence: Dρ/Dt = −ρ tr A (times the moment) for a uniform density.
  const double rate = kinematic_rates_of(p, nl, c, velocities(p)).density_rate;
  CHECK(rate == Approx(-kDensity * (A[0][0] + A[1][1] + A[2][2]) * m).epsilon(1e-9));
}

TEST_CASE("eq 12 in space: a uniform stress exerts no force inside, a linear one its divergence",
          "[stages-3d]") {
  const double dx = 1e-3;
  const int n = 9;
  const CubicSplineKernel<3> W(1.3 * dx);
  ParticlesOf<3> p = cube(n, dx);
  MomentumParamsOf<3> params;
  params.smoothing_length = W.smoothing_length();
  params.sound_speed = 50.0;
  params.gravity = {0.0, -9.81, 0.0};
  PairList<3> nl;
  nl.build(p.coordinates(), W, p.size());
  const std::size_t c = centre_of(n);
  for (std::size_t i = 0; i < p.size(); ++i)
    p.sxx[i] = -1e4, p.syy[i] = -2e4, p.szz[i] = -3e4, p.sxy[i] = 5e3, p.sxz[i] = -4e3, p.syz[i] = 2e3;
  compute_acceleration(p, nl, params);
  CHECK(p.ax[c] == Approx(0.0).margin(1e-9));
  CHECK(p.ay[c] == Approx(-9.81).epsilon(1e-12));
  CHECK(p.az[c] == Approx(0.0).margin(1e-9));
  // σ_xz = s z, σ_yz = s' z: ∂σ_xz/∂z = s gives a_x = s/ρ (× the lattice moment of the symmetric
  // form, whose pair sum Σ m (σ_i + σ_j)/ρ² ∇W reproduces ∇·σ/ρ on a regular lattice).
  const double s = 4e5, s2 = -2e5;
  for (std::size_t i = 0; i < p.size(); ++i)
    p.sxx[i] = p.syy[i] = p.szz[i] = p.sxy[i] = 0.0, p.sxz[i] = s * p.z[i], p.syz[i] = s2 * p.z[i];
  params.gravity = {0.0, 0.0, 0.0};
  compute_acceleration(p, nl, params);
  const double m = lattice_moment(W, dx);
  CHECK(p.ax[c] == Approx(s / kDensity * m).epsilon(1e-9));
  CHECK(p.ay[c] == Approx(s2 / kDensity * m).epsilon(1e-9));
  CHECK(p.az[c] == Approx(0.0).margin(1e-6));
}

TEST_CASE("the artificial stress in space: R = -eps sigma_1/rho^2 n(x)n for one tensile principal stress along n",
          "[stages-3d]") {
  ParticlesOf<3> p;
  p.resize(1, 0);
  p.density[0] = kDensity;
  // σ = σ₁ n⊗n + σ₂ (I − n⊗n), σ₁ = 300 Pa tensile along an oblique n, σ₂ = −2 kPa.
  const double n[3] = {1.0 / std::sqrt(3.0), -1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  const double s1 = 300.0, s2 = -2000.0, eps = 0.5;
  const auto sigma = [&](int a, int b) { return s1 * n[a] * n[b] + s2 * ((a == b) - n[a] * n[b]); };
  p.sxx[0] = sigma(0, 0), p.syy[0] = sigma(1, 1), p.szz[0] = sigma(2, 2);
  p.sxy[0] = sigma(0, 1), p.sxz[0] = sigma(0, 2), p.syz[0] = sigma(1, 2);
  REQUIRE(set_artificial_stress(p, 0, eps));
  const double r = -eps * s1 / (kDensity * kDensity);
  CHECK(p.rxx[0] == Approx(r * n[0] * n[0]).epsilon(1e-10));
  CHECK(p.rxy[0] == Approx(r * n[0] * n[1]).epsilon(1e-10));
  CHECK(p.ryz[0] == Approx(r * n[1] * n[2]).epsilon(1e-10));
  CHECK(p.rzz[0] == Approx(r * n[2] * n[2]).epsilon(1e-10));
  // All principal stresses compressive: no artificial stress.
  // (Eigenvalues −1.5e3 ± 1.3e3 and −3e3: beyond Gershgorin's quick test, so the decomposition decides.)
  p.sxx[0] = -1e3, p.syy[0] = -2e3, p.szz[0] = -3e3, p.sxy[0] = 1.2e3, p.sxz[0] = p.syz[0] = 0.0;
  CHECK_FALSE(set_artificial_stress(p, 0, eps));
  CHECK(p.rxx[0] == 0.0);
}

TEST_CASE("a ghost behind an oblique plane mirrors the soil: free slip reflects sigma and v, no slip keeps sigma and reverses v",
          "[stages-3d]") {
  const double dx = 1e-3;
  const int n = 7;
  ParticlesOf<3> soil = cube(n, dx);
  const std::size_t soil_count = soil.size();
  // The plane through the cube's corner with unit normal m into the soil; the ghost one spacing behind it.
  const sph::Vec3 m{0.6, 0.8, 0.0}, corner{0.0, 0.0, 0.0};
  const sph::Vec3 ghost = corner - dx * m + sph::Vec3{0.0, 0.0, 3 * dx};
  ParticlesOf<3> p;
  p.resize(soil_count, 1);
  for (std::size_t i = 0; i < soil_count; ++i) {
    p.x[i] = soil.x[i] + 0.5 * dx, p.y[i] = soil.y[i] + 0.5 * dx, p.z[i] = soil.z[i];  // in front of the plane
    p.density[i] = kDensity, p.mass[i] = soil.mass[i];
    p.sxx[i] = -1e3, p.syy[i] = -2e3, p.szz[i] = -3e3, p.sxy[i] = 4e2, p.sxz[i] = -3e2, p.syz[i] = 2e2;
    p.vx[i] = 0.3, p.vy[i] = -0.4, p.vz[i] = 0.5;
  }
  const std::size_t b = soil_count;
  p.x[b] = ghost.x, p.y[b] = ghost.y, p.z[b] = ghost.z, p.mass[b] = soil.mass[0], p.density[b] = kDensity;
  p.wall_nx[0] = m.x, p.wall_ny[0] = m.y, p.wall_nz[0] = m.z;
  PairList<3> nl;
  nl.build(p.coordinates(), CubicSplineKernel<3>(1.3 * dx), soil_count);
  REQUIRE(nl.pair_count(b) > 0);
  const double sigma[3][3] = {{-1e3, 4e2, -3e2}, {4e2, -2e3, 2e2}, {-3e2, 2e2, -3e3}}, v[3] = {0.3, -0.4, 0.5};
  const double nn[3] = {m.x, m.y, m.z};
  double R[3][3];
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) R[a][c] = (a == c) - 2.0 * nn[a] * nn[c];
  double mirrored[3][3] = {}, v_mirrored[3] = {};
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      v_mirrored[a] += R[a][c] * v[c];
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) mirrored[a][c] += R[a][k] * sigma[k][l] * R[l][c];
    }
  const MutableVelocitySpans<3> velocity{p.vx, p.vy, p.vz};
  SECTION("free slip") {
    p.wall_friction[0] = 0.0;
    mirror_stress_onto_ghost(p, nl, b);
    mirror_velocity_onto_ghost(p, nl, b, velocity);
    CHECK(p.sxx[b] == Approx(mirrored[0][0]));
    CHECK(p.sxy[b] == Approx(mirrored[0][1]));
    CHECK(p.sxz[b] == Approx(mirrored[0][2]));
    CHECK(p.syz[b] == Approx(mirrored[1][2]));
    CHECK(p.szz[b] == Approx(mirrored[2][2]));
    CHECK(p.vx[b] == Approx(v_mirrored[0]));
    CHECK(p.vy[b] == Approx(v_mirrored[1]));
    CHECK(p.vz[b] == Approx(v_mirrored[2]));
  }
  SECTION("no slip") {
    p.wall_friction[0] = std::numeric_limits<double>::infinity();
    mirror_stress_onto_ghost(p, nl, b);
    mirror_velocity_onto_ghost(p, nl, b, velocity);
    CHECK(p.sxy[b] == Approx(sigma[0][1]));
    CHECK(p.sxz[b] == Approx(sigma[0][2]));
    CHECK(p.syz[b] == Approx(sigma[1][2]));
    CHECK(p.vx[b] == Approx(-v[0]));
    CHECK(p.vz[b] == Approx(-v[2]));
  }
  CHECK(p.density[b] == Approx(kDensity));
}

// The density diffusion of eq 11 (stages/continuity.h) on the lattice, at rest, with the particles'
// masses following the density so that every volume m/ρ is dx³: nothing for a uniform or a linear
// density, and for ρ = ρ0 (1 + k x²) exactly δhc ∇²ρ = δhc 2kρ0 times the kernel's lattice moment,
// the same lattice sum as eq 23's.
TEST_CASE("eq 11's density diffusion in space: a discrete Laplacian, exact on the lattice for a quadratic",
          "[stages-3d]") {
  const double dx = 1e-3, k = 2e3, diffusion = 0.1 * 1.3 * dx * 50.0;  // δ h c (m²/s)
  const int n = 9;
  const CubicSplineKernel<3> W(1.3 * dx);
  ParticlesOf<3> p = cube(n, dx);
  PairList<3> nl;
  nl.build(p.coordinates(), W, p.size());
  const std::size_t c = centre_of(n);
  const KinematicOptions options{.density_diffusion = diffusion};
  CHECK(kinematic_rates_of(p, nl, c, velocities(p), options).density_rate == 0.0);  // uniform
  const double xc = p.x[c];
  const auto set_density = [&](auto&& rho) {
    for (std::size_t i = 0; i < p.size(); ++i)
      p.density[i] = rho(p.x[i] - xc), p.mass[i] = p.density[i] * dx * dx * dx;
  };
  set_density([](double x) { return kDensity * (1.0 + 30.0 * x); });
  CHECK(std::abs(kinematic_rates_of(p, nl, c, velocities(p), options).density_rate) < 1e-9 * kDensity);
  set_density([&](double x) { return kDensity * (1.0 + k * x * x); });
  const double rate = kinematic_rates_of(p, nl, c, velocities(p), options).density_rate;
  CHECK(rate == Approx(diffusion * 2.0 * k * kDensity * lattice_moment(W, dx)).epsilon(1e-9));
  CHECK(kinematic_rates_of(p, nl, c, velocities(p)).density_rate == 0.0);  // off: eq 11 as printed
}
