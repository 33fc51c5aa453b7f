#include "constitutive/integrators/implicit_cam_clay.h"

#include <cmath>
#include <limits>

#include "constitutive/integrators/integrator.h"

namespace soilsph {

namespace {
constexpr int kMaxIterations = 100;
constexpr double kYieldTolerance = 1e-13;     ///< |f| / (M p_c)² at convergence
constexpr double kRelativeStep = 1e-15;       ///< bracket width relative to the root at convergence
constexpr double kAbsoluteVolume = 1e-20;     ///< plastic volume below which v is converged absolutely
constexpr double kResidualTolerance = 1e-14;  ///< |r1| relative to its terms at convergence
const double kSqrt3Over2 = std::sqrt(1.5);

/// The return-mapping equations of one increment, evaluated at (v, Δλ).
class CamClayReturn {
 public:
  CamClayReturn(const ModifiedCamClay& model, const State& start, const Mat3& d_eps)
      : model_(model),
        M2_(model.M() * model.M()),
        theta_(model.hardening_exponent()),
        p_n_(mean_pressure(start.stress)),
        pc_n_(start.pc),
        d_eps_v_(-d_eps.trace()),
        s_n_(deviator(start.stress)),
        d_e_(deviator(d_eps)),
        S0_(ddot(s_n_, s_n_)),
        S1_(ddot(s_n_, d_e_)),
        S2_(ddot(d_e_, d_e_)) {}

  /// Everything that depends on (v, Δλ).
  struct Point {
    double v, l;       ///< unknowns
    double p, pc;      ///< mean pressure and p_c
    double Kt, G, dG;  ///< tangent bulk and shear moduli at p, dG/dp
    double A2, B, q2;  ///< ‖s_n + 2GΔe‖², 1 + 6GΔλ, q²
    double f;          ///< yield function (Pa²)
  };

  Point at(double v, double l) const {
    Point x{};
    x.v = v, x.l = l;
    x.p = model_.elasticity().pressure_after(p_n_, d_eps_v_ - v);
    x.pc = pc_n_ * std::exp(theta_ * v);
    const Moduli D = model_.elasticity().at(x.p);
    x.Kt = D.K, x.G = D.G, x.dG = model_.elasticity().slope_at(x.p).G;
    x.A2 = S0_ + 4.0 * x.G * S1_ + 4.0 * x.G * x.G * S2_;
    x.B = 1.0 + 6.0 * x.G * l;
    x.q2 = 1.5 * x.A2 / (x.B * x.B);
    x.f = M2_ * x.p * (x.p - x.pc) + x.q2;
    return x;
  }
  /// r1 = v − Δλ M²(2p − p_c) and its derivatives.
  double r1(const Point& x) const { return x.v - x.l * M2_ * (2.0 * x.p - x.pc); }
  double r1_v(const Point& x) const { return 1.0 + x.l * M2_ * (2.0 * x.Kt + theta_ * x.pc); }
  double r1_l(const Point& x) const { return -M2_ * (2.0 * x.p - x.pc); }
  /// ∂(q²)/∂G and ∂(q²)/∂Δλ.
  double q2_G(const Point& x) const {
    return 1.5 * ((4.0 * S1_ + 8.0 * x.G * S2_) / (x.B * x.B) - 12.0 * x.l * x.A2 / (x.B * x.B * x.B));
  }
  double q2_l(const Point& x) const { return -1.5 * 12.0 * x.G * x.A2 / (x.B * x.B * x.B); }
  /// ∂f/∂v (dp/dv = −K_t, dp_c/dv = θ p_c) and ∂f/∂Δλ.
  double f_v(const Point& x) const {
    return -M2_ * ((2.0 * x.p - x.pc) * x.Kt + theta_ * x.p * x.pc) - q2_G(x) * x.dG * x.Kt;
  }
  double f_l(const Point& x) const { return q2_l(x); }
  /// The size of the terms of f, for a round-off-aware convergence test.
  double yield_scale(const Point& x) const { return M2_ * (x.p * x.p + x.pc * x.pc) + x.q2; }

  /// v(Δλ) solving r1 = 0: r1 is increasing in v, negative at min(0, −Δλ M² p_c,n) and positive at
  /// max(0, 2Δλ M² p_trial) (p decreases and p_c increases with v).
  Point solve_volume(double l, double v_guess) const {
    const Point trial = at(0.0, l);
    double lo = std::min(0.0, -l * M2_ * pc_n_), hi = std::max(0.0, 2.0 * l * M2_ * trial.p);
    double v = std::clamp(v_guess, lo, hi);
    double last_step = hi - lo, step_before_last = 2.0 * (hi - lo);
    for (int it = 0; it < kMaxIterations; ++it) {
      const Point x = at(v, l);
      const double r = r1(x);
      // Converged when r1 is round-off of its own terms (they cancel at the root).
      if (!std::isfinite(r)) {  // p_c overflowed: v is far too large
        hi = v;
        v = 0.5 * (lo + hi);
        continue;
      }
      if (std::abs(r) <= kResidualTolerance * (std::abs(x.v) + l * M2_ * (2.0 * std::abs(x.p) + x.pc)))
        return x;
      (r < 0.0 ? lo : hi) = v;
      // Newton, bisecting when it leaves the bracket or is slower than bisection: a step larger than
      // half the one before last (rtsafe, Numerical Recipes §9.4; Newton creeps down exp(θ v)).
      const double step = r / r1_v(x);
      double next = v - step;
      if (!std::isfinite(next) || next <= lo || next >= hi ||
          2.0 * std::abs(step) > std::abs(step_before_last))
        next = 0.5 * (lo + hi);
      step_before_last = last_step;
      last_step = next - v;
      if (std::abs(next - v) <= kRelativeStep * std::abs(v) + kAbsoluteVolume ||
          hi - lo <= kRelativeStep * std::abs(v) + kAbsoluteVolume)
        return at(next, l);
      v = next;
    }
    throw IntegrationError("implicit (modified-cam-clay): the volumetric return did not converge");
  }

  /// df/dΔλ along r1 = 0: ∂f/∂Δλ + ∂f/∂v dv/dΔλ, dv/dΔλ = −r1_l/r1_v.
  double total_f_l(const Point& x) const { return f_l(x) - f_v(x) * r1_l(x) / r1_v(x); }

  /// The consistent tangent at a converged point (implicit-function theorem on r1 = 0, f = 0).
  Mat6 tangent(const Point& x, bool plastic) const {
    const double c2 = 1.5;
    const Mat3& I = identity3();
    const Mat3 a = s_n_ + 2.0 * x.G * d_e_;
    // Partial derivatives with respect to Δε at fixed (v, Δλ), as tensors t with dφ = t : dΔε.
    const Mat3 grad_p = -x.Kt * I;
    const Mat3 grad_G = x.dG * grad_p;
    Mat3 grad_v = Mat3::Zero(), grad_l = Mat3::Zero();
    if (plastic) {
      const Mat3 grad_r1 = -2.0 * x.l * M2_ * grad_p;
      const Mat3 grad_q2 = c2 * 4.0 * x.G / (x.B * x.B) * a + q2_G(x) * grad_G;
      const Mat3 grad_f = M2_ * (2.0 * x.p - x.pc) * grad_p + grad_q2;
      const double J11 = r1_v(x), J12 = r1_l(x), J21 = f_v(x), J22 = f_l(x);
      const double det = J11 * J22 - J12 * J21;
      grad_v = -(J22 * grad_r1 - J12 * grad_f) / det;
      grad_l = -(-J21 * grad_r1 + J11 * grad_f) / det;
    }
    const Mat3 grad_p_total = grad_p - x.Kt * grad_v;
    // σ = −p I + a/B with a = s_n + 2GΔe, B = 1 + 6GΔλ, G = G(p).
    return -voigt_outer(I, grad_p_total) +
           (2.0 * voigt_outer(d_e_, x.dG * grad_p_total) + 2.0 * x.G * voigt_deviatoric_projector()) / x.B -
           voigt_outer(a, 6.0 * x.l * x.dG * grad_p_total + 6.0 * x.G * grad_l) / (x.B * x.B);
  }

  Mat3 stress(const Point& x) const { return (s_n_ + 2.0 * x.G * d_e_) / x.B - x.p * identity3(); }
  double M2() const { return M2_; }

 private:
  const ModifiedCamClay& model_;
  double M2_, theta_, p_n_, pc_n_, d_eps_v_;
  Mat3 s_n_, d_e_;
  double S0_, S1_, S2_;
};
}  // namespace

State implicit_update(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent) {
  if (!(start.pc > 0.0)) throw IntegrationError("implicit (modified-cam-clay): p_c must be positive");
  const CamClayReturn eqs(model, start, strain_increment);
  State next = start;
  next.plastic_multiplier = 0.0;
  const auto trial = eqs.at(0.0, 0.0);
  if (trial.f <= 0.0) {
    next.stress = eqs.stress(trial);
    if (tangent) *tangent = eqs.tangent(trial, false);
    return next;
  }

  // Outer safeguarded Newton on Δλ: f > 0 on [0, lo], f < 0 at hi once found.
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  double l = 0.0;
  auto x = trial;
  {
    // A first estimate from the trial's normal, n:D:n (the scale of the multiplier).
    const double n_p = eqs.M2() * (2.0 * trial.p - trial.pc);
    const double scale = trial.f / (trial.Kt * n_p * n_p + 12.0 * trial.G * trial.q2 + 1e-300);
    l = scale;
  }
  bool converged = false;
  double last_step = std::numeric_limits<double>::infinity(), step_before_last = last_step;
  for (int it = 0; it < kMaxIterations; ++it) {
    x = eqs.solve_volume(l, x.v);
    if (std::abs(x.f) <= kYieldTolerance * eqs.yield_scale(x) || hi - lo <= kRelativeStep * l) {
      converged = true;
      break;
    }
    (x.f > 0.0 ? lo : hi) = l;
    const double step = x.f / eqs.total_f_l(x);
    double next = l - step;
    // Bisect when Newton leaves the bracket or is slower than bisection (it can cycle where f(Δλ)
    // bends); double Δλ while no upper bracket is known.
    const bool slow = 2.0 * std::abs(step) > std::abs(step_before_last);
    if (!std::isfinite(next) || next <= lo || next >= hi || (slow && std::isfinite(hi)))
      next = std::isfinite(hi) ? 0.5 * (lo + hi) : 2.0 * l;
    step_before_last = last_step;
    last_step = next - l;
    l = next;
  }
  if (!converged || !std::isfinite(x.f))
    throw IntegrationError("implicit (modified-cam-clay): the return mapping did not converge");

  next.stress = eqs.stress(x);
  next.pc = x.pc;
  const Mat3 n_g = model.flow_direction(next.stress, next.pc);
  accumulate_plastic_strain(next, x.l * n_g);
  next.plastic_multiplier = x.l;
  if (tangent) *tangent = eqs.tangent(x, true);
  return next;
}

}  // namespace soilsph
