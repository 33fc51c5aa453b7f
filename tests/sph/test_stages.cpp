// The SPH stages on fields with known answers: continuity (eq 11), momentum (eq 12, 36-38) and the
// artificial stress (Gray et al. 2001), in the interior of a lattice.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "constitutive/rotation.h"
#include "helpers.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/stages/artificial_stress.h"
#include "sph/stages/continuity.h"
#include "sph/stages/kernel_ratio_power.h"
#include "sph/stages/momentum.h"
#include "sph/stages/stress_update.h"
#include "sph/stages/velocity_gradient.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
constexpr double kDx = 1.0e-3, kRho = 2000.0;
constexpr int kN = 15;

/// Lattice kernel moment m = Σ_j V (x_j − x_i) ∂W/∂x_i for a full neighbourhood, from the formula.
double lattice_moment(const CubicSpline& W) {
  double m = 0.0;
  for (int a = -4; a <= 4; ++a)
    for (int b = -4; b <= 4; ++b) {
      const double xj = a * kDx, r = std::hypot(a * kDx, b * kDx);
      if (r > 0.0) m += kDx * kDx * xj * W.derivative(r) * (-xj) / r;
    }
  return m;
}

bool interior(const Particles& p, std::size_t i) {
  const double lo = 3.5 * kDx, hi = (kN - 4.5) * kDx;
  return p.x[i] > lo && p.x[i] < hi && p.y[i] > lo && p.y[i] < hi;
}
}  // namespace

TEST_CASE("eq 11: a uniform expansion lowers the density at rate 2 e rho (times the moment)", "[stages]") {
  const CubicSpline W(1.3 * kDx);
  Particles p = test::lattice(kN, kDx, kRho);
  const double e = 0.8;  // 1/s, v = e x
  for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = e * p.x[i], p.vy[i] = e * p.y[i];
  NeighbourList nl;
  nl.build(p.x, p.y, W);
  compute_density_rate(p, nl);
  const double m = lattice_moment(W);
  for (std::size_t i = 0; i < p.soil_count; ++i)
    if (interior(p, i)) CHECK(p.density_rate[i] == Approx(-2.0 * e * kRho * m).epsilon(1e-10));
}

TEST_CASE("eq 12: a stress gradient accelerates by dsigma/dx / rho, a uniform stress not at all",
          "[stages]") {
  const CubicSpline W(1.3 * kDx);
  Particles p = test::lattice(kN, kDx, kRho);
  const double s0 = -500.0, a = 4.0e4, b = -2.5e4;  // Pa, Pa/m
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.sxx[i] = s0 + a * p.x[i];  // ∂σxx/∂x = a
    p.syy[i] = s0;
    p.sxy[i] = b * p.x[i];  // ∂σyx/∂x = b drives y
  }
  NeighbourList nl;
  nl.build(p.x, p.y, W);
  MomentumParams params;
  params.sound_speed = 26.0;
  params.smoothing_length = W.smoothing_length();
  params.gravity = {0.0, -9.81};
  compute_acceleration(p, nl, params);
  const double m = lattice_moment(W);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    if (!interior(p, i)) continue;
    // Σ V_j (σ_i + σ_j) ∇W = 2σ_i Σ V∇W + a M = a m (Σ V ∇W = 0 on the lattice).
    CHECK(p.ax[i] == Approx(a * m / kRho).epsilon(1e-9));
    CHECK(p.ay[i] == Approx(b * m / kRho - 9.81).epsilon(1e-9));
  }
}

TEST_CASE("eq 37: the viscosity pushes approaching particles apart and leaves receding ones", "[stages]") {
  const CubicSpline W(1.3 * kDx);
  for (const double v : {0.5, -0.5}) {  // particle 0 moves towards (+) or away from (−) particle 1
    Particles p;
    p.resize(2, 0);
    p.x = {0.0, kDx}, p.y = {0.0, 0.0}, p.vx = {v, 0.0}, p.vy = {0.0, 0.0};
    p.density = {kRho, kRho}, p.mass = {kRho * kDx * kDx, kRho * kDx * kDx};
    NeighbourList nl;
    nl.build(p.x, p.y, W);
    MomentumParams params;
    params.viscosity_alpha = 1.0, params.viscosity_beta = 1.0, params.sound_speed = 26.0;
    params.smoothing_length = W.smoothing_length(), params.gravity = {0.0, 0.0};
    compute_acceleration(p, nl, params);
    if (v > 0) {
      // φ = h v·r/(r² + 0.01h²) with v·r = −v Δp; Π = (−α c φ + β φ²)/ρ; a0 = −m Π ∂W/∂x_0.
      const double h = W.smoothing_length();
      const double phi = h * (-v * kDx) / (kDx * kDx + 0.01 * h * h);
      const double pi = (-26.0 * phi + phi * phi) / kRho;
      const double grad = W.derivative(kDx) * (-kDx) / kDx;  // ∂W/∂x_0, x_0 − x_1 = −Δp
      CHECK(p.ax[0] == Approx(-p.mass[1] * pi * grad));
      CHECK(p.ax[0] < 0.0);  // decelerated, away from particle 1
      CHECK(p.ax[1] == Approx(-p.ax[0]));
    } else {
      CHECK(p.ax[0] == 0.0);
      CHECK(p.ax[1] == 0.0);
    }
  }
}

TEST_CASE("artificial stress: -eps sigma/rho^2 on tensile principal stresses only, rotated back",
          "[stages]") {
  // Principal stresses (σ_a, σ_b) along (c, s) and (−s, c): R = −ε Σ max(σ_k, 0)/ρ² n_k ⊗ n_k, for
  // axes in every quadrant of 2θ, one or both tensile, and an isotropic tension (no axes).
  const double eps = 0.5;
  struct Case {
    double a, b, theta;
  };
  for (const Case k : {Case{300.0, -800.0, 0.4}, Case{300.0, -800.0, 1.2}, Case{-800.0, 300.0, -0.9},
                       Case{300.0, 120.0, 2.0}, Case{50.0, -1.0, 0.0}, Case{-5.0, 70.0, 1.5707963267948966},
                       Case{200.0, 200.0, 0.3}}) {
    const double c = std::cos(k.theta), s = std::sin(k.theta);
    Particles p = test::lattice(2, kDx, kRho);
    p.sxx[0] = k.a * c * c + k.b * s * s, p.syy[0] = k.a * s * s + k.b * c * c,
    p.sxy[0] = (k.a - k.b) * c * s;
    p.sxx[1] = -800.0, p.syy[1] = -1600.0, p.sxy[1] = -240.0;  // compression only
    compute_artificial_stress(p, eps);
    const double ra = -eps * std::max(k.a, 0.0) / (kRho * kRho),
                 rb = -eps * std::max(k.b, 0.0) / (kRho * kRho);
    const double scale = eps * 800.0 / (kRho * kRho);
    CHECK(p.rxx[0] == Approx(ra * c * c + rb * s * s).margin(1e-12 * scale));
    CHECK(p.ryy[0] == Approx(ra * s * s + rb * c * c).margin(1e-12 * scale));
    CHECK(p.rxy[0] == Approx((ra - rb) * c * s).margin(1e-12 * scale));
    CHECK(p.rxx[1] == 0.0);
    CHECK(p.ryy[1] == 0.0);
    CHECK(p.rxy[1] == 0.0);
  }
}

TEST_CASE("a rigid rotation turns the stress with the body (eq 23 spin, Jaumann terms)", "[stages]") {
  const CubicSpline W(1.3 * kDx);
  Particles p = test::lattice(kN, kDx, kRho);
  const double omega = 3.0, dt = 1e-3, S = 700.0;  // rad/s counter-clockwise, s, Pa
  for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = -omega * p.y[i], p.vy[i] = omega * p.x[i];
  for (std::size_t i = 0; i < p.soil_count; ++i) p.state[i].stress(0, 0) = -S;  // uniaxial along x
  NeighbourList nl;
  nl.build(p.x, p.y, W);
  compute_velocity_gradient(p, nl);
  const LinearElastic model({kRho, 1.0e6, 0.3});
  update_stress(model, p, dt);
  // Eq 23 gives the spin −ω m (ω̇_xy = ½(∂vx/∂y − ∂vy/∂x)) and no strain rate; the Hughes–Winget
  // rotation turns by θ with tan(θ/2) = ω m dt/2, counter-clockwise like the body:
  // σ' = −S (cos θ, sin θ) ⊗ (cos θ, sin θ).
  const double theta = 2.0 * std::atan(0.5 * omega * lattice_moment(W) * dt);
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    if (!interior(p, i)) continue;
    CHECK(p.sxx[i] == Approx(-S * std::cos(theta) * std::cos(theta)).epsilon(1e-9));
    CHECK(p.syy[i] == Approx(-S * std::sin(theta) * std::sin(theta)).epsilon(1e-9));
    CHECK(p.sxy[i] == Approx(-S * std::cos(theta) * std::sin(theta)).epsilon(1e-9));
  }
}

namespace {
/// A model whose update fails for one particle's state (marked by pc), as a scheme's IntegrationError.
struct FailingModel {
  State update(const State& state, const Mat3&, const Mat3&) const {
    if (state.pc == 13.0) throw IntegrationError("no convergence");
    return state;
  }
};
}  // namespace

TEST_CASE("a failed stress update is an error naming the particle, not a crash in the parallel loop",
          "[sph][stress]") {
  Particles p = test::lattice(6, 1.0e-3, 2000.0);
  p.state[17].pc = 13.0;
  CHECK_THROWS_AS(update_stress(FailingModel{}, p, 1e-5), IntegrationError);
  CHECK_THROWS_WITH(update_stress(FailingModel{}, p, 1e-5),
                    Catch::Matchers::Contains("soil particle 17: no convergence"));
}

namespace {
/// A model whose update fails for strain increments larger than `largest` (as an implicit return
/// that does not converge for a coarse increment) and otherwise adds the increment to the stress.
struct CoarseFailingModel {
  double largest;
  State update(const State& state, const Mat3& strain, const Mat3&) const {
    if (strain.norm() > largest) throw IntegrationError("no convergence");
    State s = state;
    s.stress += strain;
    return s;
  }
};
}  // namespace

TEST_CASE(
    "a failed stress update is redone in parts, then by the fallback, then stress-free if it had no stress",
    "[sph][stress]") {
  Mat3 strain = Mat3::Zero();
  strain(0, 0) = 1.0;
  StepFailure log;
  const CoarseFailingModel fails{0.0}, succeeds{2.0};
  // Fails whole, succeeds in 4 parts (each 0.25): the parts add up to the whole increment.
  const State s =
      update_splitting_on_failure(CoarseFailingModel{0.3}, fails, State{}, strain, Mat3::Zero(), log);
  CHECK(s.stress(0, 0) == Approx(1.0).epsilon(1e-15));
  CHECK(log.fallback_updates() == 1);
  CHECK_FALSE(log.failed());
  // 16 parts of 1/16 still too large: the fallback does it whole.
  const State f =
      update_splitting_on_failure(CoarseFailingModel{0.05}, succeeds, State{}, strain, Mat3::Zero(), log);
  CHECK(f.stress(0, 0) == 1.0);
  CHECK(log.fallback_updates() == 2);
  // The fallback fails too: a particle with stress is an error, a stress-free one stays stress-free.
  State loaded;
  loaded.stress(1, 1) = -100.0;
  CHECK_THROWS_AS(
      update_splitting_on_failure(CoarseFailingModel{0.05}, fails, loaded, strain, Mat3::Zero(), log),
      IntegrationError);
  State vanished;
  vanished.stress(0, 0) = -2e-11, vanished.pc = 5e-11;
  const State free =
      update_splitting_on_failure(CoarseFailingModel{0.05}, fails, vanished, strain, Mat3::Zero(), log);
  CHECK(free.stress.norm() == 0.0);
  CHECK(free.pc == 5e-11);
  CHECK(log.fallback_updates() == 4);
  // An update that succeeds whole is not counted.
  update_splitting_on_failure(succeeds, fails, State{}, strain, Mat3::Zero(), log);
  CHECK(log.fallback_updates() == 4);
}

namespace {
/// CoarseFailingModel that also turns the stress with the spin increment (constitutive/rotation.h).
struct CoarseFailingRotatingModel {
  double largest;
  State update(const State& state, const Mat3& strain, const Mat3& spin) const {
    if (strain.norm() > largest) throw IntegrationError("no convergence");
    return rotate_state(state, spin);
  }
};
}  // namespace

TEST_CASE("a failed stress update redone in parts turns the stress by each part's share of the spin",
          "[sph][stress]") {
  // A uniaxial stress σ_xx = 1 kPa and an in-plane spin of 0.02 rad over the step: whole, the update
  // turns it by 2 atan(0.01) (the Cayley rotation of rotation.h); in two parts each turns it by
  // 2 atan(0.005), together within O(θ³) = 1e-6 of the whole. Each part turned by the whole spin would
  // turn it twice as far.
  Mat3 strain = Mat3::Zero(), spin = Mat3::Zero();
  strain(0, 0) = 1.0;
  spin(0, 1) = 0.02, spin(1, 0) = -0.02;
  State start;
  start.stress(0, 0) = 1000.0;
  StepFailure log;
  const CoarseFailingRotatingModel fails{0.0};
  const State whole = CoarseFailingRotatingModel{2.0}.update(start, strain, spin);
  const State parts =
      update_splitting_on_failure(CoarseFailingRotatingModel{0.6}, fails, start, strain, spin, log);
  REQUIRE(log.fallback_updates() == 1);
  const double angle = std::atan2(whole.stress(0, 1), whole.stress(0, 0));  // of the turned principal axis
  CHECK(std::abs(angle) > 0.004);
  CHECK((parts.stress - whole.stress).norm() < 1e-6 * 1000.0);
}

TEST_CASE("the fallback of a model with a choice of scheme is its substep twin", "[sph][stress]") {
  ModifiedCamClay::Params params;  // Table 1 (the constructor checks every parameter)
  params.density = 2000.0, params.poisson_ratio = 0.3, params.friction_angle = 35.0;
  params.compression_index = 0.085, params.swelling_index = 0.019, params.initial_void_ratio = 0.68;
  params.integrator = Integrator::Implicit;
  CHECK(fallback_model(ModifiedCamClay(params)).integrator() == Integrator::Substep);
}

TEST_CASE(
    "Modified Cam-Clay with hardening_volume = current: the stress update carries each particle's volume",
    "[stages][hardening-volume]") {
  // Uniform plane-strain compression vx = −r x, vy = −r y on a lattice (no spin): eq 23 gives each
  // interior particle Δε_xx = Δε_yy = −r m dt per step, so after n steps its volumetric strain is
  // −2 n r m dt, which the hardening exponent v/(λ−κ) = (1+e0)(1 + ε_v)/(λ−κ) reads. The particle's
  // state must be the model's own updates chained (verified against closed forms in
  // tests/verification/test_cross_code.cpp), and differ from the initial volume's.
  const CubicSpline W(1.3 * kDx);
  const double m = lattice_moment(W), dt = 1e-3, step_strain = 2e-4, r = step_strain / (m * dt);
  constexpr int kSteps = 100;  // ε_v = −0.04
  ModifiedCamClay::Params params;
  params.density = kRho, params.poisson_ratio = 0.3, params.friction_angle = 30.0;
  params.compression_index = 0.077, params.swelling_index = 0.0066, params.initial_void_ratio = 0.788;
  params.elasticity = Elasticity::Kind::PressureDependent;
  params.integrator = Integrator::Implicit;
  State start;
  start.stress = -200e3 * Mat3::Identity();
  start.pc = 200e3;
  double pc_of[2];
  for (HardeningVolume volume : {HardeningVolume::Current, HardeningVolume::Initial}) {
    params.hardening_volume = volume;
    const ModifiedCamClay model(params);
    Particles p = test::lattice(kN, kDx, kRho);
    for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = -r * p.x[i], p.vy[i] = -r * p.y[i];
    for (std::size_t i = 0; i < p.soil_count; ++i) p.state[i] = start;
    NeighbourList nl;
    nl.build(p.x, p.y, W);
    compute_velocity_gradient(p, nl);
    for (int k = 0; k < kSteps; ++k) update_stress(model, p, dt);
    State chained = start;
    const Mat3 increment = soilsph::Vec3(-step_strain, -step_strain, 0.0).asDiagonal();
    for (int k = 0; k < kSteps; ++k) chained = model.update(chained, increment, Mat3::Zero());
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      if (!interior(p, i)) continue;
      if (volume == HardeningVolume::Current)
        CHECK(p.state[i].volumetric_strain == Approx(-2.0 * kSteps * step_strain).epsilon(1e-9));
      CHECK(p.state[i].pc == Approx(chained.pc).epsilon(1e-8));
      CHECK((p.state[i].stress - chained.stress).norm() <= 1e-8 * chained.stress.norm());
    }
    pc_of[volume == HardeningVolume::Current ? 0 : 1] = chained.pc;
  }
  CHECK(std::abs(pc_of[0] / pc_of[1] - 1.0) > 1e-2);
}

TEST_CASE("eq 12 with the artificial stress: (1 - eps) T / rho^2 on a pair with one particle in tension",
          "[stages]") {
  // Two particles a spacing apart along x, at rest (no viscosity), one in uniaxial tension T along
  // x, the other stress-free: R = -eps T / rho^2 along x on the tensile one (artificial_stress.h),
  // f_ij = W(dp)/W(dp) = 1, so a_0 = m_1 (T/rho^2 + R_xx) dW_01/dx_0 = m_1 (1 - eps) T/rho^2 dW/dx_0,
  // whichever of the two carries the tension (the sum over i and j is symmetric).
  const CubicSpline W(1.3 * kDx);
  const double T = 200.0, eps = 0.5;                     // Pa
  const double grad = W.derivative(kDx) * (-kDx) / kDx;  // ∂W/∂x_0, x_0 − x_1 = −Δp
  for (const std::size_t tensile : {std::size_t{0}, std::size_t{1}})
    for (const bool enabled : {true, false}) {
      Particles p;
      p.resize(2, 0);
      p.x = {0.0, kDx}, p.y = {0.0, 0.0}, p.vx = {0.0, 0.0}, p.vy = {0.0, 0.0};
      p.density = {kRho, kRho}, p.mass = {kRho * kDx * kDx, kRho * kDx * kDx};
      p.sxx = {0.0, 0.0}, p.syy = {0.0, 0.0}, p.sxy = {0.0, 0.0};
      p.sxx[tensile] = T;
      NeighbourList nl;
      nl.build(p.x, p.y, W);
      MomentumParams params;
      params.sound_speed = 26.0, params.smoothing_length = W.smoothing_length(), params.gravity = {0.0, 0.0};
      params.artificial_stress = enabled ? ArtificialStress(eps, 2.55, W, kDx) : ArtificialStress{};
      compute_artificial_stress(p, eps);
      compute_acceleration(p, nl, params);
      const double factor = enabled ? 1.0 - eps : 1.0;
      CAPTURE(tensile, enabled);
      CHECK(p.ax[0] == Approx(p.mass[1] * factor * T / (kRho * kRho) * grad).epsilon(1e-12));
      CHECK(p.ax[1] == Approx(-p.ax[0]).epsilon(1e-12));
      CHECK(p.ay[0] == 0.0);
    }
}

TEST_CASE("the artificial stress's weight f^n from its table is within the Hermite bound of pow",
          "[stages]") {
  // Cubic Hermite on 1024 intervals of W in [0, W(0)]: on [f_k, f_k+1] the error is at most
  // Δ⁴/384 max|d⁴(f^n)/df⁴| (kernel_ratio_power.h); the first interval, where f^n is not four times
  // differentiable for n < 4, only within 1e-8. Linear interpolation, or a slope not scaled by the
  // step, fails the bound by orders of magnitude.
  constexpr std::size_t kIntervals = 1024;
  for (const double ratio : {1.0, 1.3, 2.0})
    for (const double n : {1.0, 2.55, 4.0, 5.5}) {
      const CubicSpline W(ratio * kDx);
      const double w_dp = W.value(kDx), step = W.value(0.0) / kIntervals / w_dp;  // Δ in f
      const KernelRatioPower weight(n, w_dp, W.value(0.0), kIntervals);
      CAPTURE(ratio, n);
      for (int k = 0; k <= 20000; ++k) {
        const double w = W.value(2.0 * W.smoothing_length() * k / 20000.0), f = w / w_dp;
        const double exact = std::pow(f, n), error = std::abs(weight(w) - exact);
        const double lo = std::floor(f / step) * step, hi = lo + step;
        const double d4 = std::abs(n * (n - 1.0) * (n - 2.0) * (n - 3.0)) *
                          std::max(std::pow(lo, n - 4.0), std::pow(hi, n - 4.0));
        const double bound = lo > 0.0 ? std::pow(step, 4) / 384.0 * d4 : 1e-8;
        CHECK(error <= bound + 1e-14 * std::max(1.0, exact));  // + rounding
      }
    }
}

TEST_CASE("a viscoplastic material carries the overstress G rate tau of its relaxation time in simple shear",
          "[stages][viscoplastic]") {
  // Shear without spin, vx = ½γ̇ y, vy = ½γ̇ x, held on a lattice: eq 23 gives the engineering shear
  // rate γ̇ m and no spin (a spin would turn the shear stress into normal stresses by the Jaumann
  // terms). D-P past yield at constant p
  // (ψ = 0) then settles where the Duvaut–Lions step stands still, σ_xy = τ_y + G γ̇ m τ
  // (constitutive/viscoplastic_relaxation.h), τ_y = k + 3α p0 from the paper's match (eq 17–18);
  // without the key on τ_y itself.
  const CubicSpline W(1.3 * kDx);
  const double E = 1.0e8, nu = 0.3, c = 1.0e4, phi = 35.0, p0 = 1.0e5, G = E / (2.0 * (1.0 + nu));
  const double t = std::tan(phi * M_PI / 180.0), root = std::sqrt(9.0 + 12.0 * t * t);
  const double yield_shear = 3.0 * c / root + 3.0 * t / root * p0;
  const double rate = 1.0 / lattice_moment(W), dt = 1e-4;  // γ̇ m = 1/s
  for (const double tau : {0.0, 1e-3}) {
    DruckerPrager::Params params{};
    params.density = kRho, params.young_modulus = E, params.poisson_ratio = nu, params.friction_angle = phi;
    params.cohesion = c, params.viscoplastic_relaxation_time = tau;
    const DruckerPrager model(params);
    Particles p = test::lattice(kN, kDx, kRho);
    for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = 0.5 * rate * p.y[i], p.vy[i] = 0.5 * rate * p.x[i];
    for (std::size_t i = 0; i < p.soil_count; ++i) p.state[i].stress = -p0 * Mat3::Identity();
    NeighbourList nl;
    nl.build(p.x, p.y, W);
    compute_velocity_gradient(p, nl);
    for (int k = 0; k < 1000; ++k) update_stress(model, p, dt);  // 0.1 s: yield at 1.6 ms, then 98 τ
    const double expected = yield_shear + G * 1.0 * tau;
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      if (!interior(p, i)) continue;
      CHECK(p.sxy[i] == Approx(expected).epsilon(1e-9));
      CHECK(-(p.sxx[i] + p.syy[i] + p.state[i].stress(2, 2)) / 3.0 == Approx(p0).epsilon(1e-12));
    }
  }
}
