// The ghost mirrors of sph/stages/boundaries.h at an oblique wall, against values worked out by hand:
// a ghost with two soil neighbours at the same distance (so its kernel average is their mean) behind
// a wall of normal n = (3/5, 4/5), tangent t = (−n_y, n_x) = (−4/5, 3/5).
//
// The soil's mean stress σ̄ = [[−1200, 200], [200, −2800]] Pa has, on the wall,
//   σ̄·n = (−560, −2120),  σ̄_nn = −2032,  σ̄_nt = t·σ̄·n = 448 − 1272 = −824,  σ̄_tt = −1968 Pa;
// the ghost keeps σ_nn, σ_tt and takes σ_nt = 2τ − σ̄_nt (τ the wall's shear traction), so in x, y
//   σ_b = σ_nn n⊗n + σ_tt t⊗t + σ_b,nt (n⊗t + t⊗n),
//   n⊗n = [[.36, .48], [.48, .64]],  t⊗t = [[.64, −.48], [−.48, .36]],  n⊗t + t⊗n = [[−.96, −.28], [−.28, .96]].
// The soil's mean velocity v̄ = (0.2, 0.1) m/s: v̄·n = 0.2, v̄·t = −0.1.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sph/kernel.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/stages/boundaries.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
constexpr double kNx = 0.6, kNy = 0.8, kTx = -0.8, kTy = 0.6;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Ghost 2 at the origin; soil 0 and 1 at a n ± b t in front of the wall, a = 1 mm, b = 0.5 mm.
struct ObliqueWall {
  Particles p;
  NeighbourList nl;
  static constexpr std::size_t kGhost = 2;

  ObliqueWall(double mu, double wall_vx = 0.0, double wall_vy = 0.0) {
    p.resize(2, 1);
    const double a = 1e-3, b = 0.5e-3;
    p.x[0] = a * kNx + b * kTx, p.y[0] = a * kNy + b * kTy;
    p.x[1] = a * kNx - b * kTx, p.y[1] = a * kNy - b * kTy;
    p.sxx[0] = -1000.0, p.syy[0] = -3000.0, p.sxy[0] = 400.0;
    p.sxx[1] = -1400.0, p.syy[1] = -2600.0, p.sxy[1] = 0.0;
    p.vx[0] = 0.3, p.vy[0] = -0.1;
    p.vx[1] = 0.1, p.vy[1] = 0.3;
    p.density[0] = 2000.0, p.density[1] = 1800.0, p.density[kGhost] = 1234.0;
    for (std::size_t i = 0; i < 3; ++i) p.mass[i] = 2e-3;
    p.wall_nx[0] = kNx, p.wall_ny[0] = kNy, p.wall_friction[0] = mu;
    p.wall_vx[0] = wall_vx, p.wall_vy[0] = wall_vy;
    nl.build(p.x, p.y, CubicSpline(1.3e-3), p.soil_count);
    REQUIRE(nl.pair_count(kGhost) == 2);
    double w[2] = {};
    nl.for_each_pair(kGhost, [&](const NeighbourList::Pair& q) { w[q.j] = q.w; });
    REQUIRE(w[0] == Approx(w[1]).epsilon(1e-12));  // so the kernel average is the mean
  }
  void mirror_stress(Vec2 body = {}) { mirror_stress_onto_ghost(p, nl, kGhost, body); }
  Vec2 mirrored_velocity() {
    mirror_velocity_onto_ghost(p, nl, kGhost, {p.vx, p.vy});
    return {p.vx[kGhost], p.vy[kGhost]};
  }
  void check_stress(double sxx, double syy, double sxy) const {
    CHECK(p.sxx[kGhost] == Approx(sxx).epsilon(1e-12));
    CHECK(p.syy[kGhost] == Approx(syy).epsilon(1e-12));
    CHECK(p.sxy[kGhost] == Approx(sxy).epsilon(1e-12).margin(1e-9));
  }
};

void check_velocity(Vec2 v, double vx, double vy) {
  CHECK(v.x == Approx(vx).margin(1e-14));
  CHECK(v.y == Approx(vy).margin(1e-14));
}
}  // namespace

TEST_CASE("ghost mirror, free slip at an oblique wall: the shear stress and the normal velocity reversed",
          "[boundaries][mirror]") {
  ObliqueWall w(0.0);
  w.mirror_stress();
  // σ_b,nt = −σ̄_nt = +824: xx = −2032(.36) − 1968(.64) + 824(−.96), yy = −2032(.64) − 1968(.36) + 824(.96),
  // xy = −2032(.48) − 1968(−.48) + 824(−.28).
  w.check_stress(-2782.08, -1217.92, -261.44);
  CHECK(w.p.density[ObliqueWall::kGhost] == Approx(1900.0).epsilon(1e-12));  // the mean, not the ghost's own
  CHECK(w.p.wall_stick[0] == 0.0);
  // v_b = v̄ − 2 (v̄·n) n = (0.2, 0.1) − 0.4 (0.6, 0.8): the tangential velocity copied.
  check_velocity(w.mirrored_velocity(), -0.04, -0.22);
}

TEST_CASE("ghost mirror, free slip at a moving oblique wall: mirrored relative to the wall",
          "[boundaries][mirror]") {
  ObliqueWall w(0.0, 0.05, 0.0);
  w.mirror_stress();
  w.check_stress(-2782.08, -1217.92, -261.44);  // the wall's motion leaves the stress mirror
  // Δv = v̄ − v_w = (0.15, 0.1), Δv·n = 0.17: v_b = (0.2, 0.1) − 0.34 (0.6, 0.8) = (−0.004, −0.172).
  check_velocity(w.mirrored_velocity(), -0.004, -0.172);
}

TEST_CASE("ghost mirror, no slip at an oblique wall: the stress copied, the velocity 2 v_w - v_mean",
          "[boundaries][mirror]") {
  SECTION("a wall at rest") {
    ObliqueWall w(kInfinity);
    w.mirror_stress();
    w.check_stress(-1200.0, -2800.0, 200.0);
    CHECK(w.p.wall_stick[0] == 1.0);
    check_velocity(w.mirrored_velocity(), -0.2, -0.1);
  }
  SECTION("a wall moving at (0.05, 0) m/s") {
    ObliqueWall w(kInfinity, 0.05, 0.0);
    w.mirror_stress();
    w.check_stress(-1200.0, -2800.0, 200.0);
    check_velocity(w.mirrored_velocity(), -0.1, -0.1);
  }
}

TEST_CASE("ghost mirror, frictional oblique wall: Coulomb's limit mu sigma'_n, against the slip or the demand",
          "[boundaries][mirror]") {
  // σ'_n = −σ̄_nn = 2032 Pa.
  SECTION("sliding (v_mean.t = -0.1 m/s), mu = 0.25: tau = -508 Pa against the slip, velocity as free slip") {
    ObliqueWall w(0.25);
    w.mirror_stress();
    // σ_b,nt = 2(−508) + 824 = −192: xx = −731.52 − 1259.52 + 184.32, yy = −1300.48 − 708.48 − 184.32,
    // xy = −975.36 + 944.64 + 53.76.
    w.check_stress(-1806.72, -2193.28, 23.04);
    CHECK(w.p.wall_stick[0] == 0.0);
    check_velocity(w.mirrored_velocity(), -0.04, -0.22);
  }
  SECTION("sliding the other way (the wall at -0.2 t m/s, slip dv.t = -0.1 + 0.2): tau = +508 Pa") {
    ObliqueWall w(0.25, -0.2 * kTx, -0.2 * kTy);
    // σ_b,nt = 2(508) + 824 = 1840.
    w.mirror_stress();
    w.check_stress(-2032.0 * 0.36 - 1968.0 * 0.64 + 1840.0 * -0.96, -2032.0 * 0.64 - 1968.0 * 0.36 + 1840.0 * 0.96,
                   -2032.0 * 0.48 + 1968.0 * 0.48 + 1840.0 * -0.28);
    CHECK(w.p.wall_stick[0] == 0.0);
  }
  SECTION("sticking (the wall moves with the soil along t), mu = 0.5: |sigma_nt| = 824 < 1016, as no slip") {
    ObliqueWall w(0.5, -0.1 * kTx, -0.1 * kTy);  // v_w = −0.1 t: Δv = 0.2 n, no slip along the wall
    w.mirror_stress();
    w.check_stress(-1200.0, -2800.0, 200.0);
    CHECK(w.p.wall_stick[0] == 1.0);
    // v_b = 2 v_w − v̄ = (0.16, −0.12) − (0.2, 0.1).
    check_velocity(w.mirrored_velocity(), -0.04, -0.22);
  }
  SECTION("not slipping but demanding more than the limit, mu = 0.25: tau = -508 Pa with the sign of sigma_nt") {
    ObliqueWall w(0.25, -0.1 * kTx, -0.1 * kTy);
    w.mirror_stress();
    w.check_stress(-1806.72, -2193.28, 23.04);
    CHECK(w.p.wall_stick[0] == 0.0);
  }
  SECTION("a wall in tension holds no shear") {
    ObliqueWall w(0.5);
    for (std::size_t j = 0; j < 2; ++j) w.p.sxx[j] *= -1.0, w.p.syy[j] *= -1.0, w.p.sxy[j] *= -1.0;
    w.mirror_stress();
    // σ̄ = −(the compressive mean): σ̄_nn = +2032, σ̄_nt = +824, σ̄_tt = +1968; free slip's σ_b,nt = −824.
    w.check_stress(2032.0 * 0.36 + 1968.0 * 0.64 - 824.0 * -0.96, 2032.0 * 0.64 + 1968.0 * 0.36 - 824.0 * 0.96,
                   2032.0 * 0.48 - 1968.0 * 0.48 - 824.0 * -0.28);
    CHECK(w.p.wall_stick[0] == 0.0);
  }
}

TEST_CASE("ghost mirror: the soil's weight carried to the ghost along the oblique normal", "[boundaries][mirror]") {
  // Δ = −(b·n) Σ_j W ρ_j n·(x_b − x_j) / Σ_j W with n·(x_b − x_j) = −a for both neighbours:
  // b = (0, −9.81), b·n = −7.848, Δ = −7.848 · 1900 · 1e-3 = −14.9112 Pa added along n⊗n.
  ObliqueWall w(kInfinity);
  w.mirror_stress({0.0, -9.81});
  const double delta = -7.848 * 1900.0 * 1e-3;
  w.check_stress(-1200.0 + 0.36 * delta, -2800.0 + 0.64 * delta, 200.0 + 0.48 * delta);
}

TEST_CASE("ghost mirror: a ghost without soil neighbours carries no stress and no velocity", "[boundaries][mirror]") {
  ObliqueWall w(0.0);
  Particles& p = w.p;
  p.x[0] = p.x[1] = 1.0;  // far beyond the support
  NeighbourList far;
  far.build(p.x, p.y, CubicSpline(1.3e-3), p.soil_count);
  REQUIRE(far.pair_count(ObliqueWall::kGhost) == 0);
  p.sxx[ObliqueWall::kGhost] = 5.0, p.vx[ObliqueWall::kGhost] = 1.0;
  mirror_stress_onto_ghost(p, far, ObliqueWall::kGhost);
  CHECK(p.sxx[ObliqueWall::kGhost] == 0.0);
  CHECK(p.density[ObliqueWall::kGhost] == 1234.0);
  mirror_velocity_onto_ghost(p, far, ObliqueWall::kGhost, {p.vx, p.vy});
  CHECK(p.vx[ObliqueWall::kGhost] == 0.0);
  CHECK(p.vy[ObliqueWall::kGhost] == 0.0);
}

TEST_CASE("ghost mirror: a frictional wall demanded exactly its limit slides (it sticks only strictly within)",
          "[boundaries][mirror]") {
  // A floor (n = (0, 1), t = (−1, 0)) under σ̄_yy = −1000 Pa, σ̄_xy = −500 Pa: σ̄_nt = −σ̄_xy = 500 Pa, exactly
  // μ σ'_n for μ = 0.5. The soil at rest on the wall: the traction is the limit either way, but the
  // wall holds the soil (stick 1) only while |σ̄_nt| < μ σ'_n (stages/boundaries.h).
  Particles p;
  p.resize(1, 1);
  p.x[1] = 0.0, p.y[1] = 0.0;
  p.x[0] = 0.0, p.y[0] = 1e-3;
  p.syy[0] = -1000.0, p.sxy[0] = -500.0, p.density[0] = p.density[1] = 2000.0, p.mass[0] = p.mass[1] = 2e-3;
  p.wall_nx[0] = 0.0, p.wall_ny[0] = 1.0, p.wall_friction[0] = 0.5;
  NeighbourList nl;
  nl.build(p.x, p.y, CubicSpline(1.3e-3), p.soil_count);
  REQUIRE(nl.pair_count(1) == 1);
  mirror_stress_onto_ghost(p, nl, 1);
  CHECK(p.wall_stick[0] == 0.0);
  CHECK(p.sxy[1] == -500.0);  // τ = 500 Pa: σ_b,nt = 2τ − σ̄_nt = σ̄_nt, the stress copied
  p.wall_friction[0] = 0.5 + 1e-12;  // just within the limit: sticks
  mirror_stress_onto_ghost(p, nl, 1);
  CHECK(p.wall_stick[0] == 1.0);
}
