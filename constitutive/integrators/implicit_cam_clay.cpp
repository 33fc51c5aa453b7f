#include "constitutive/integrators/implicit_cam_clay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "constitutive/integrators/drift_correction.h"
#include "constitutive/integrators/integrator.h"

namespace soilsph {

namespace {
constexpr int kMaxIterations = 200;
constexpr double kYieldTolerance = 1e-13;     ///< |f| / (M p_c)² at convergence
constexpr double kRoundOffFactor = 8.0;       ///< |f| within this many times its round-off is converged
constexpr double kRelativeStep = 1e-15;       ///< bracket width relative to the root at convergence
constexpr double kAbsoluteVolume = 1e-20;     ///< plastic volume below which v is converged absolutely
constexpr double kResidualTolerance = 1e-14;  ///< |r1| relative to its terms at convergence
constexpr int kJointIterations = 12;           ///< plain Newton on (v, Δλ) before the safeguarded solver

/// The terms of an increment Δε from `start` that the entry search and the return equations share,
/// computed once per update.
struct IncrementTerms {
  IncrementTerms(const State& start, const Mat3& d_eps)
      : p_n(mean_pressure(start.stress)),
        pc_n(start.pc),
        d_eps_v(-d_eps.trace()),
        s_n(deviator(start.stress)),
        d_e(deviator(d_eps)),
        S0(ddot(s_n, s_n)),
        S1(ddot(s_n, d_e)),
        S2(ddot(d_e, d_e)) {}
  double p_n, pc_n, d_eps_v;  ///< p_n, p_c,n, Δε_v (compression-positive)
  Mat3 s_n, d_e;              ///< dev σ_n, dev Δε
  double S0, S1, S2;          ///< s_n:s_n, s_n:Δe, Δe:Δe
};

/// Where the elastic path σ_e(t) = σ_n + D_sec(tΔε):tΔε of an increment meets the yield surface, and
/// how that point moves with Δε: the flow of the increment starts there. t = 0 (the start itself)
/// unless the start is strictly inside.
struct YieldEntry {
  double t = 0.0;              ///< elastic fraction of the increment
  double p = 0.0;              ///< p_e(t)
  Mat3 s = Mat3::Zero();       ///< s_e(t) = s_n + 2 G_e(t) t Δe, G_e(t) = G_sec(p_n, tΔε_v)
  Mat3 grad_p = Mat3::Zero();  ///< dp_e(t*(Δε), Δε)/dΔε
  // ds_e/dΔε = 2t Δe ⊗ grad_G + 2 G t 𝕀_dev + ds_dt ⊗ grad_t:
  double G = 0.0;              ///< G_e(t)
  Mat3 grad_G = Mat3::Zero();  ///< ∂G_e/∂Δε at fixed t
  Mat3 ds_dt = Mat3::Zero();   ///< ∂s_e/∂t
  Mat3 grad_t = Mat3::Zero();  ///< dt*/dΔε

  /// The entry of an increment that starts on the surface: the start itself, fixed.
  static YieldEntry at(const IncrementTerms& increment) {
    YieldEntry entry;
    entry.p = increment.p_n, entry.s = increment.s_n;
    return entry;
  }
  /// X : ds_e/dΔε, a stress-like tensor.
  Mat3 contract_ds(const Mat3& X, const Mat3& d_e) const {
    return 2.0 * t * ddot(X, d_e) * grad_G + 2.0 * G * t * deviator(X) + ddot(X, ds_dt) * grad_t;
  }
  /// ds_e/dΔε as a Voigt matrix.
  Mat6 ds(const Mat3& d_e) const {
    return 2.0 * t * voigt_outer(d_e, grad_G) + 2.0 * G * t * voigt_deviatoric_projector() +
           voigt_outer(ds_dt, grad_t);
  }
};

/// The entry point of a plastic increment: F(t) = f(σ_e(t), p_c,n) = 0 on (0, 1) with F(0) < 0 < F(1),
/// by safeguarded Newton with the exact F'(t); t* then moves with Δε as dt* = −∂F/∂Δε / F'(t*).
YieldEntry yield_entry(const ModifiedCamClay& model, const IncrementTerms& increment) {
  const Elasticity& elasticity = model.elasticity();
  const double M2 = model.M() * model.M(), pc = increment.pc_n;
  const double p_n = increment.p_n, d_eps_v = increment.d_eps_v;
  const Mat3 &s_n = increment.s_n, &d_e = increment.d_e;
  const double S0 = increment.S0, S1 = increment.S1, S2 = increment.S2;
  YieldEntry entry = YieldEntry::at(increment);
  const double f_start = M2 * p_n * (p_n - pc) + 1.5 * S0;
  if (!(f_start < -kYieldTolerance * M2 * pc * pc)) return entry;  // on (or beyond) the surface

  struct Value {
    double F, dF_dt, p, K, G, dG;  ///< F, F'(t), p_e, K_t(p_e), G_e, dG_sec/dε at tΔε_v
  };
  auto value = [&](double t) {
    Value v{};
    const ElasticVolumeStep step = elasticity.volume_step(p_n, t * d_eps_v);
    v.p = step.p, v.K = step.tangent.K, v.G = step.secant.G, v.dG = step.secant_slope.G;
    const double Gt = v.G * t, dGt_dt = v.G + t * v.dG * d_eps_v;
    v.F = M2 * v.p * (v.p - pc) + 1.5 * (S0 + 4.0 * Gt * S1 + 4.0 * Gt * Gt * S2);
    v.dF_dt = M2 * (2.0 * v.p - pc) * v.K * d_eps_v + 1.5 * (4.0 * S1 + 8.0 * Gt * S2) * dGt_dt;
    return v;
  };
  double lo = 0.0, hi = 1.0, t = 0.5;
  Value v = value(t);
  for (int it = 0; it < kMaxIterations; ++it) {
    if (std::abs(v.F) <= kYieldTolerance * M2 * (v.p * v.p + pc * pc)) break;
    (v.F < 0.0 ? lo : hi) = t;
    double next = t - v.F / v.dF_dt;
    if (!std::isfinite(next) || next <= lo || next >= hi) next = 0.5 * (lo + hi);
    if (hi - lo <= kRelativeStep) break;
    t = next;
    v = value(t);
  }
  entry.t = t, entry.p = v.p, entry.G = v.G;
  entry.s = s_n + 2.0 * v.G * t * d_e;
  // Partial derivatives at fixed t, then through t*(Δε).
  const Mat3& I = identity3();
  const Mat3 grad_p_fixed_t = -v.K * t * I;  // dΔε_v = −I : dΔε
  entry.grad_G = -v.dG * t * I;
  entry.ds_dt = 2.0 * (v.G + t * v.dG * d_eps_v) * d_e;
  const double dF_dp = M2 * (2.0 * v.p - pc);
  const Mat3 dF_ds = 3.0 * entry.s;
  const Mat3 grad_F =
      dF_dp * grad_p_fixed_t + 2.0 * t * ddot(dF_ds, d_e) * entry.grad_G + 2.0 * v.G * t * deviator(dF_ds);
  entry.grad_t = -grad_F / v.dF_dt;
  entry.grad_p = grad_p_fixed_t + v.K * d_eps_v * entry.grad_t;
  return entry;
}

/// The return-mapping equations of one increment, evaluated at (v, Δλ), for the generalised
/// midpoint rule with a stiffness limiter. The flow integral over the increment is
///   Δε^p = w_t n_g(σ_t, p_c,n) + w_e n_g(σ_{n+1}, p_c),  w_t + w_e = Δλ,
/// where σ_t is the increment's entry to the yield surface (the start when that is on it):
///   w_t = min((1−α)Δλ, 1/(6G)),  w_e = Δλ − w_t.
/// Without the cap this is the generalised midpoint rule (Ortiz & Popov 1985), second order for
/// α = ½; s = a/B with a = s_n + 2GΔe − 6G w_t s_t and B = 1 + 6G w_e. For an entry at the start
/// the factor of s_n in a, 1 − 6G w_t, is the trapezoidal rule's amplification 1 − z/2 of the stiff
/// shear mode (z = 6GΔλ). Past z = 2 it turns negative: the uncapped rule then has several roots
/// and its return jumps between them as Δε changes (on a drained OCR 30 path with 2–10 increments the
/// driver's Newton, without splitting, completed 2 of 9 runs; with the cap, 8). The cap keeps that
/// factor ≥ 0, is continuous in Δε, and tends to backward Euler as z → ∞; below the cap nothing
/// changes.
/// Volumetric part: r1 = v − M²[w_t (2p_t − p_c,n) + w_e (2p − p_c)], p_c = p_c(v) of eq 27 with the
/// softening bound p_c,min (ModifiedCamClay::hardened).
class CamClayReturn {
 public:
  CamClayReturn(const ModifiedCamClay& model, const IncrementTerms& increment, double alpha,
                const YieldEntry& entry)
      : model_(model),
        entry_(entry),
        alpha_(alpha),
        M2_(model.M() * model.M()),
        theta_(model.hardening_exponent()),
        p_n_(increment.p_n),
        pc_n_(increment.pc_n),
        d_eps_v_(increment.d_eps_v),
        s_n_(increment.s_n),
        d_e_(increment.d_e),
        S0_(increment.S0),
        S1_(increment.S1),
        S2_(increment.S2),
        // An entry at the start (t = 0) is s_n itself (YieldEntry::at).
        T0_(entry.t > 0.0 ? ddot(entry.s, s_n_) : S0_),
        T1_(entry.t > 0.0 ? ddot(entry.s, d_e_) : S1_),
        T2_(entry.t > 0.0 ? ddot(entry.s, entry.s) : S0_),
        entry_flow_p_(2.0 * entry.p - pc_n_),
        p_trial_(model.elasticity().pressure_after(p_n_, d_eps_v_)) {}

  /// Everything that depends on (v, Δλ).
  struct Point {
    double v, l;              ///< unknowns
    double p, pc;             ///< mean pressure and p_c
    double theta;             ///< d ln p_c/dv: θ, or 0 where softening has stopped at p_c,min
    double Kt, G, dG;         ///< tangent bulk modulus at p, secant shear modulus, dG/dp
    double wt, wt_l, wt_G;    ///< the entry's flow weight w_t and its partials ∂/∂Δλ, ∂/∂G
    double kG, B;             ///< 6G w_t (the weight of s_t in a) and B = 1 + 6G w_e
    double a_sn, a_de, a_st;  ///< a : s_n, a : Δe, a : s_t
    double A2, q2;            ///< a : a, q² = 1.5 a:a/B²
    double f;                 ///< yield function (Pa²)
    double we() const { return l - wt; }
    // Partials of kG and B with respect to G and Δλ (w_e = Δλ − w_t).
    double kG_G() const { return 6.0 * (wt + G * wt_G); }
    double kG_l() const { return 6.0 * G * wt_l; }
    double B_G() const { return 6.0 * (we() - G * wt_G); }
    double B_l() const { return 6.0 * G * (1.0 - wt_l); }
  };

  Point at(double v, double l) const {
    Point x{};
    x.v = v, x.l = l;
    const Elasticity& elasticity = model_.elasticity();
    const double elastic_volume = d_eps_v_ - v;
    const ElasticVolumeStep step = elasticity.volume_step(p_n_, elastic_volume);
    x.p = step.p;
    // Eq 27 exact over the increment, softening no further than p_c,min (ModifiedCamClay::hardened):
    // p_c(v) is continuous and non-decreasing, flat below the bound.
    x.pc = model_.hardened(pc_n_, v);
    x.theta = model_.hardening_exponent_at(x.pc, v);
    x.Kt = step.tangent.K;
    x.G = step.secant.G;
    // G and p are both functions of the elastic volume alone, so dG/dp = (dG/dε_v^e)/K_t.
    x.dG = step.secant_slope.G / x.Kt;
    const double cap = 1.0 / (6.0 * x.G);
    if ((1.0 - alpha_) * l <= cap) {
      x.wt = (1.0 - alpha_) * l, x.wt_l = 1.0 - alpha_, x.wt_G = 0.0;
    } else {
      x.wt = cap, x.wt_l = 0.0, x.wt_G = -cap / x.G;
    }
    x.kG = 6.0 * x.G * x.wt;
    x.B = 1.0 + 6.0 * x.G * x.we();
    x.a_sn = S0_ + 2.0 * x.G * S1_ - x.kG * T0_;
    x.a_de = S1_ + 2.0 * x.G * S2_ - x.kG * T1_;
    x.a_st = T0_ + 2.0 * x.G * T1_ - x.kG * T2_;
    x.A2 = x.a_sn + 2.0 * x.G * x.a_de - x.kG * x.a_st;
    x.q2 = 1.5 * x.A2 / (x.B * x.B);
    x.f = M2_ * x.p * (x.p - x.pc) + x.q2;
    return x;
  }
  /// The volumetric flow integral w_t M^-2 n_p(entry) + w_e M^-2 n_p(end), n_p = M²(2p − p_c) being
  /// the compression-positive volumetric part of n_g.
  double volumetric_flow(const Point& x) const { return x.wt * entry_flow_p_ + x.we() * (2.0 * x.p - x.pc); }
  /// r1 = v − M² (volumetric flow) and its derivatives; dG/dv = −dG/dp K_t.
  double r1(const Point& x) const { return x.v - M2_ * volumetric_flow(x); }
  double r1_v(const Point& x) const {
    return 1.0 + M2_ * (x.we() * (2.0 * x.Kt + x.theta * x.pc) +
                        (entry_flow_p_ - (2.0 * x.p - x.pc)) * x.wt_G * x.dG * x.Kt);
  }
  double r1_l(const Point& x) const {
    return -M2_ * (x.wt_l * entry_flow_p_ + (1.0 - x.wt_l) * (2.0 * x.p - x.pc));
  }
  /// a : ∂a/∂G and a : ∂a/∂Δλ: ∂a/∂G = 2Δe − ∂(kG)/∂G s_t, ∂a/∂Δλ = −∂(kG)/∂Δλ s_t.
  double a_dot_a_G(const Point& x) const { return 2.0 * x.a_de - x.kG_G() * x.a_st; }
  double a_dot_a_l(const Point& x) const { return -x.kG_l() * x.a_st; }
  /// ∂(q²)/∂G and ∂(q²)/∂Δλ of q² = 1.5 ‖a‖²/B².
  double q2_G(const Point& x) const {
    return 1.5 * (2.0 * a_dot_a_G(x) / (x.B * x.B) - 2.0 * x.A2 * x.B_G() / (x.B * x.B * x.B));
  }
  double q2_l(const Point& x) const {
    return 1.5 * (2.0 * a_dot_a_l(x) / (x.B * x.B) - 2.0 * x.A2 * x.B_l() / (x.B * x.B * x.B));
  }
  /// ∂f/∂v (dp/dv = −K_t, dp_c/dv = θ p_c with the point's θ) and ∂f/∂Δλ.
  double f_v(const Point& x) const {
    return -M2_ * ((2.0 * x.p - x.pc) * x.Kt + x.theta * x.p * x.pc) - q2_G(x) * x.dG * x.Kt;
  }
  double f_l(const Point& x) const { return q2_l(x); }
  /// The size of the terms of f, for a relative convergence test.
  double yield_scale(const Point& x) const { return M2_ * (x.p * x.p + x.pc * x.pc) + x.q2; }
  /// The round-off of f at x: p = p_n + ΔP(Δε_v − v) carries ε (|p_n| + |p| + K_t(|Δε_v| + |v|)), which
  /// dominates where the surface is tiny against the trial stress (a dilated free-surface particle:
  /// p_c ≈ 1e-8 Pa after a 100 Pa tensile trial).
  double yield_round_off(const Point& x) const {
    return M2_ * std::abs(2.0 * x.p - x.pc) * pressure_round_off(x) +
           std::numeric_limits<double>::epsilon() * yield_scale(x);
  }
  double pressure_round_off(const Point& x) const {
    return std::numeric_limits<double>::epsilon() *
           (std::abs(p_n_) + std::abs(x.p) + x.Kt * (std::abs(d_eps_v_) + std::abs(x.v)));
  }
  /// A point where f can vanish: q² = M² p (p_c − p) ≥ 0 needs p ≥ 0 (to round-off). Where p_c has
  /// grown by orders of magnitude (Newton far out on exp(θv)), |f| falls below the round-off of its
  /// enormous terms at a tensile p that no root has (a dust return once stopped at v = 13, p = −1e7
  /// Pa, p_c = 1e143 Pa): the fast path's round-off acceptance must not take such a point.
  bool can_be_root(const Point& x) const { return x.p >= -kRoundOffFactor * pressure_round_off(x); }
  /// |f| within kYieldTolerance of its terms or, once the root is bracketed, within its round-off.
  bool converged(const Point& x, bool bracketed) const {
    const double round_off = bracketed ? kRoundOffFactor * yield_round_off(x) : 0.0;
    return std::abs(x.f) <= std::max(kYieldTolerance * yield_scale(x), round_off);
  }

  /// r1 is round-off of its own terms (they cancel at the root).
  bool volume_converged(const Point& x) const {
    return std::abs(r1(x)) <= kResidualTolerance * (std::abs(x.v) + x.l * M2_ * (2.0 * std::abs(x.p) + x.pc));
  }

  /// The fast path: plain Newton on (r1, B² f) = 0 in (v, Δλ) together (newton_from), from one of two
  /// starts, both with the first-order estimate Δλ_1 = entry_estimate():
  ///  - the estimate's own flow, v = Δλ_1 M² (2p_t − p_c,n) (or, when Δλ_1 is not positive, Δλ = `l`,
  ///    the trial's estimate, and the v of its flow at the trial): right where the increment is
  ///    small against the surface;
  ///  - the stress kept at the entry, v = (1 − t)Δε_v, all the volume change after the entry plastic
  ///    (then p = p_t exactly, for either elasticity): the limit of an increment whose plastic shear
  ///    dwarfs the elastic one, z = 6G Δλ_1 ≫ 1 (a free-surface particle whose surface, p_c ~ 1e-8–20
  ///    Pa, is tiny against one step's trial, ~100 Pa). From the first start Newton fails there: v is
  ///    right to a few per cent, but K δv then moves p by more than the surface's size.
  /// The stress-kept start goes first where z > 2 (for the default α = ½ the z at which the midpoint's
  /// shear amplification 1 − z/2 turns negative and the stiffness cap below takes over; thresholds from
  /// 1 to 10 cost the same), the other one when the first fails. In the SPH collapse (MCC, 1 mm) the
  /// first start then converges for all but ~100 of 8.4e6 returns and the second for those; with the
  /// flow start alone 4.7 % failed, and the safeguarded solver that took them over made about 35 % of
  /// all evaluations of the return's equations (docs/method/integrators.md).
  std::optional<Point> solve_jointly(double l) const {
    const EntryEstimate first_order = entry_estimate();
    const double l1 = first_order.multiplier;
    const auto from_flow = [&] {
      return newton_from(l1 > 0.0 ? at(l1 * M2_ * entry_flow_p_, l1)
                                  : at(M2_ * volumetric_flow(at(0.0, l)), l));
    };
    const auto from_kept_stress = [&]() -> std::optional<Point> {
      if (!(l1 > 0.0)) return std::nullopt;
      return newton_from(at((1.0 - entry_.t) * d_eps_v_, l1));
    };
    if (first_order.shear_relaxation > 2.0) {
      if (std::optional<Point> x = from_kept_stress()) return x;
      return from_flow();
    }
    if (std::optional<Point> x = from_flow()) return x;
    return from_kept_stress();
  }

  /// Plain Newton on (r1, B² f) = 0 in (v, Δλ) from x. The normal at the trial, which the safeguarded
  /// solver's estimate uses, is far off where one increment's trial lies many times the surface's size
  /// outside it (a particle at low pressure), and Newton then needs many steps; hence the starts of
  /// solve_jointly. One evaluation per iteration, where the safeguarded solver below (an inner Newton
  /// on v for every outer Δλ) took about 50 per return in the SPH collapse. B² f instead of f:
  /// q² = 1.5‖a‖²/B² makes f(Δλ) strongly convex when one increment's shear is large against the
  /// surface, and Newton then creeps; B² f has the same root (B > 0) and is nearly quadratic in Δλ. A
  /// Δλ step below zero is replaced by halving Δλ.
  /// Converged when the safeguarded solver's tests hold or, where the surface is tiny against the
  /// trial (p_c ≪ 1 Pa after a 100 Pa trial) and |f| cannot reach kYieldTolerance of its terms, when
  /// |f| is within its round-off and either r1 has converged or Newton's step is below round-off of
  /// (v, Δλ) (with ∂r1/∂v ≫ 1, r1 cannot fall below ∂r1/∂v times an ulp of v); the safeguarded solver
  /// accepts the same round-off only once it has bracketed the root, so these tests apply only to an
  /// iterate inside v's bracket (in_volume_bracket), where the round-off estimate is sane, and where
  /// a root can be (can_be_root).
  /// Returns nothing, and the caller falls back to the safeguarded solver, if an iterate is not
  /// finite, leaves the bracket, or has not converged after kJointIterations.
  std::optional<Point> newton_from(Point x) const {
    for (int it = 0; it < kJointIterations; ++it) {
      if (!std::isfinite(x.f) || !in_volume_bracket(x.v, x.l)) return std::nullopt;
      // Every test is relative to the size of f's terms, which a runaway p_c inflates: none holds
      // where no root can be.
      const bool root = can_be_root(x);
      const bool f_round_off = root && std::abs(x.f) <= kRoundOffFactor * yield_round_off(x);
      if (root && volume_converged(x) && (converged(x, false) || f_round_off)) return x;
      // d(B²f) = B² df + 2B f dB; B depends on Δλ and, through G(p), on v (dp/dv = −K_t).
      const double B2 = x.B * x.B, B_v = -x.B_G() * x.dG * x.Kt, F = B2 * x.f, r = r1(x);
      const double a = r1_v(x), b = r1_l(x);
      const double c = B2 * f_v(x) + 2.0 * x.B * B_v * x.f, d = B2 * f_l(x) + 2.0 * x.B * x.B_l() * x.f;
      const double det = a * d - b * c;
      const double v = x.v - (d * r - b * F) / det, l_step = x.l - (a * F - c * r) / det;
      if (f_round_off && std::abs(v - x.v) <= kRelativeStep * std::abs(x.v) + kAbsoluteVolume &&
          std::abs(l_step - x.l) <= kRelativeStep * x.l)
        return x;
      x = at(v, l_step > 0.0 ? l_step : 0.5 * x.l);
    }
    return std::nullopt;
  }

  /// The first-order Δλ with the normal at the entry, n_t : D : Δε / (n_t : D : n_t), with
  /// n = −n_p I/3 + 3s: n:D:Δε = K n_p Δε_v + 6G s_t:Δe, n:D:n = K n_p² + 18G s_t:s_t (moduli at p_t),
  /// and z = 6G Δλ, the increment's plastic shear relaxation against the elastic shear.
  struct EntryEstimate {
    double multiplier, shear_relaxation;
  };
  EntryEstimate entry_estimate() const {
    const ElasticVolumeStep moduli = model_.elasticity().volume_step(entry_.p, 0.0);
    const double K = moduli.tangent.K, G = moduli.secant.G, n_p = M2_ * entry_flow_p_;
    const double l = (K * n_p * d_eps_v_ + 6.0 * G * T1_) / (K * n_p * n_p + 18.0 * G * T2_);
    return {l, 6.0 * G * l};
  }

  /// The bracket of v at Δλ = l that solve_volume starts from (see there); its lower end holds only
  /// when the trial is not tensile.
  struct VolumeBracket {
    double lo, hi;
    bool tensile;
  };
  VolumeBracket volume_bracket(double l) const {
    return {std::min(0.0, -l * M2_ * pc_n_), std::max(0.0, 2.0 * l * M2_ * std::max(entry_.p, p_trial_)),
            std::min(entry_.p, p_trial_) < 0.0};
  }
  /// v within that bracket (below its upper end, and above its lower end unless the trial is tensile).
  bool in_volume_bracket(double v, double l) const {
    const VolumeBracket b = volume_bracket(l);
    return v <= b.hi && (b.tensile || v >= b.lo);
  }

  /// v(Δλ) solving r1 = 0. The flow's weights are positive and sum to Δλ, p decreases and p_c
  /// increases with v, so r1 is positive at max(0, 2Δλ M² max(p_t, p_trial)) and, while p ≥ 0 for
  /// v ≤ 0, negative at min(0, −Δλ M² p_c,n). A tensile trial (p < 0: constant elasticity, or below
  /// the floor) can put the root lower; the lower end is then doubled until r1 < 0 there.
  Point solve_volume(double l, double v_guess) const {
    auto [lo, hi, tensile] = volume_bracket(l);
    if (tensile) {
      for (int k = 0; k < kMaxIterations && lo < 0.0 && r1(at(lo, l)) > 0.0; ++k) {
        hi = lo;
        lo *= 2.0;
      }
    }
    double v = std::clamp(v_guess, lo, hi);
    double last_step = hi - lo, step_before_last = 2.0 * (hi - lo);
    for (int it = 0; it < kMaxIterations; ++it) {
      const Point x = at(v, l);
      const double r = r1(x);
      // Converged when r1 is round-off of its own terms (they cancel at the root).
      if (!std::isfinite(r)) {
        // p_c overflowed (v far too large: r1 → +∞) or, on the swelling line, p did (v far too
        // negative: r1 → −∞).
        (v > 0.0 ? hi : lo) = v;
        v = 0.5 * (lo + hi);
        continue;
      }
      if (volume_converged(x)) return x;
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

  /// The consistent tangent at a converged point (implicit-function theorem on r1 = 0, f = 0, with
  /// the entry (p_t, s_t) moving with Δε).
  Mat6 tangent(const Point& x, bool plastic) const {
    const Mat3& I = identity3();
    const Mat3 a = s_n_ + 2.0 * x.G * d_e_ - x.kG * entry_.s;
    // Partial derivatives with respect to Δε at fixed (v, Δλ), as tensors t with dφ = t : dΔε.
    const Mat3 grad_p = -x.Kt * I;
    const Mat3 grad_G = x.dG * grad_p;
    Mat3 grad_v = Mat3::Zero(), grad_l = Mat3::Zero();
    if (plastic) {
      const Mat3 grad_r1 = -M2_ * (2.0 * x.we() * grad_p + 2.0 * x.wt * entry_.grad_p +
                                   (entry_flow_p_ - (2.0 * x.p - x.pc)) * x.wt_G * grad_G);
      // q² through a: ∂a/∂Δe = 2G, ∂a/∂s_t = −kG; through G: q2_G.
      const Mat3 grad_q2 = 1.5 * 4.0 * x.G / (x.B * x.B) * a + q2_G(x) * grad_G -
                           1.5 * 2.0 * x.kG / (x.B * x.B) * entry_.contract_ds(a, d_e_);
      const Mat3 grad_f = M2_ * (2.0 * x.p - x.pc) * grad_p + grad_q2;
      const double J11 = r1_v(x), J12 = r1_l(x), J21 = f_v(x), J22 = f_l(x);
      const double det = J11 * J22 - J12 * J21;
      grad_v = -(J22 * grad_r1 - J12 * grad_f) / det;
      grad_l = -(-J21 * grad_r1 + J11 * grad_f) / det;
    }
    // σ = −p I + a/B: da = 2Δe dG + 2G dΔe − s_t d(kG) − kG ds_t, with kG and B functions of (G, Δλ).
    const Mat3 grad_p_total = grad_p - x.Kt * grad_v;
    const Mat3 grad_G_total = x.dG * grad_p_total;
    const Mat3 grad_kG = x.kG_G() * grad_G_total + x.kG_l() * grad_l;
    const Mat3 grad_B = x.B_G() * grad_G_total + x.B_l() * grad_l;
    return -voigt_outer(I, grad_p_total) +
           (2.0 * voigt_outer(d_e_, grad_G_total) + 2.0 * x.G * voigt_deviatoric_projector() -
            voigt_outer(entry_.s, grad_kG) - x.kG * entry_.ds(d_e_)) /
               x.B -
           voigt_outer(a, grad_B) / (x.B * x.B);
  }

  Mat3 stress(const Point& x) const {
    return (s_n_ + 2.0 * x.G * d_e_ - x.kG * entry_.s) / x.B - x.p * identity3();
  }
  double M2() const { return M2_; }
  const YieldEntry& entry() const { return entry_; }
  /// dε^p:dε^p of the flow integral w_t n_g(σ_t) + w_e n_g(σ_{n+1}), n_g = −M²(2p − p_c)/3 I + 3s:
  /// its trace is −M² (volumetric flow) and its deviator 3(w_t s_t + w_e s), s = a/B, so
  /// dε^p:dε^p = (M² flow)²/3 + 9(w_t² s_t:s_t + 2 w_t w_e a:s_t/B + w_e² a:a/B²).
  double plastic_strain_squared_norm(const Point& x) const {
    const double volume = M2_ * volumetric_flow(x), wt = x.wt, we = x.we();
    return volume * volume / 3.0 +
           9.0 * (wt * wt * T2_ + 2.0 * wt * we * x.a_st / x.B + we * we * x.A2 / (x.B * x.B));
  }

 private:
  const ModifiedCamClay& model_;
  const YieldEntry& entry_;
  double alpha_;
  double M2_, theta_, p_n_, pc_n_, d_eps_v_;
  Mat3 s_n_, d_e_;
  double S0_, S1_, S2_;  ///< s_n:s_n, s_n:Δe, Δe:Δe
  double T0_, T1_, T2_;  ///< s_t:s_n, s_t:Δe, s_t:s_t
  double entry_flow_p_;  ///< 2p_t − p_c,n: the volumetric flow direction at the entry, over M²
  double p_trial_;       ///< p of the elastic trial
};

/// The plastic return of an increment, with the equations `eqs` from its entry to the surface, whose
/// elastic trial (`trial`, evaluated with any entry: at Δλ = 0 only its entry-free fields are read) is
/// outside the surface.
State plastic_return(const ModifiedCamClay& model, const State& start, const CamClayReturn& eqs,
                     const CamClayReturn::Point& trial, Mat6* tangent, ReturnEstimate* estimate) {
  const YieldEntry& entry = eqs.entry();
  // Outer safeguarded Newton on Δλ: f > 0 on [0, lo], f < 0 at hi once found.
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  // A first estimate from the trial's normal, n:D:n (the scale of the multiplier).
  const double n_p = eqs.M2() * (2.0 * trial.p - trial.pc);
  double l = trial.f / (trial.Kt * n_p * n_p + 12.0 * trial.G * trial.q2 + 1e-300);
  auto x = trial;
  const std::optional<CamClayReturn::Point> fast = eqs.solve_jointly(l);
  bool converged = fast.has_value();
  if (fast) {
    x = *fast;
  } else {
    // The fallback starts from the larger of the trial's estimate and the entry's (the fast path's
    // start), which for a dust return far outside its surface is orders of magnitude closer: 7× fewer
    // outer steps over a collapse, with the same root on every return (docs/method/integrators.md).
    l = std::max(l, eqs.entry_estimate().multiplier);
  }
  double last_step = std::numeric_limits<double>::infinity(), step_before_last = last_step;
  for (int it = 0; !converged && it < kMaxIterations; ++it) {
    x = eqs.solve_volume(l, x.v);
    if (eqs.can_be_root(x) && eqs.converged(x, std::isfinite(hi))) {
      converged = true;
      break;
    }
    if (hi - lo <= kRelativeStep * l) {  // a sign change pinned to round-off of f (hi is finite)
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
  if (!converged || !std::isfinite(x.f) || !(x.l >= 0.0))
    throw IntegrationError("implicit (modified-cam-clay): the return mapping did not converge");

  State next = start;
  next.stress = eqs.stress(x);
  next.pc = x.pc;
  accumulate_plastic_strain_from_squared_norm(next, eqs.plastic_strain_squared_norm(x));
  next.plastic_multiplier = x.l;
  if (tangent) *tangent = eqs.tangent(x, true);
  if (estimate) {
    // Half the difference between the stress and p_c changes of forward and backward Euler, whose
    // flows are Δλ n(σ_t) and Δλ n(σ_{n+1}) (Sloan, Abbo & Sheng 2001, with implicit ends): D:Δn
    // = −K_t M² Δn_p I + 6G (s − s_t), Δn_p = (2p − p_c) − (2p_t − p_c,n); dp_c/p_c = θ Δλ M² Δn_p.
    const double dn_p = (2.0 * x.p - x.pc) - (2.0 * entry.p - start.pc);
    const Mat3 ds = deviator(next.stress) - entry.s;
    const double dn_stress =
        std::sqrt(3.0 * std::pow(x.Kt * eqs.M2() * dn_p, 2) + 36.0 * x.G * x.G * ddot(ds, ds));
    const double scale = std::max({std::sqrt(ddot(next.stress, next.stress)),
                                   std::sqrt(ddot(start.stress, start.stress)), 1.0});
    estimate->euler = 0.5 * x.l *
                   std::max(dn_stress / scale, model.hardening_exponent() * eqs.M2() * std::abs(dn_p));
  }
  return next;
}

constexpr int kMaxSubincrements = 10000;
constexpr double kMinFraction = 1e-6;  ///< smallest sub-increment, as a fraction of the increment
}  // namespace

State implicit_return(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent, ReturnEstimate* estimate) {
  if (estimate) *estimate = ReturnEstimate{};
  if (!(start.pc > 0.0)) throw IntegrationError("implicit (modified-cam-clay): p_c must be positive");
  const IncrementTerms increment(start, strain_increment);
  if (!tangent) {
    // Most updates of a collapse are elastic (59 % in the MCC scene at 1 mm): their trial, with the
    // arithmetic of CamClayReturn::at(0, 0) and stress() term for term (Δλ = 0 makes w_t = 0, B = 1
    // and p_c = p_c,n exactly), so the result is the same to the bit, without the return's set-up.
    const ElasticVolumeStep step = model.elasticity().volume_step(increment.p_n, increment.d_eps_v);
    const double G = step.secant.G, p = step.p, M2 = model.M() * model.M();
    const double a_sn = increment.S0 + 2.0 * G * increment.S1, a_de = increment.S1 + 2.0 * G * increment.S2;
    if (M2 * p * (p - start.pc) + 1.5 * (a_sn + 2.0 * G * a_de) <= 0.0) {
      State next = start;
      next.plastic_multiplier = 0.0;
      next.stress = increment.s_n + 2.0 * G * increment.d_e - p * identity3();
      return next;
    }
  }
  // The elastic trial (Δλ = 0: the flow weights and the entry play no part).
  const YieldEntry start_entry = YieldEntry::at(increment);
  const CamClayReturn eqs(model, increment, model.implicit_alpha(), start_entry);
  const CamClayReturn::Point trial = eqs.at(0.0, 0.0);
  if (trial.f <= 0.0) {
    State next = start;
    next.plastic_multiplier = 0.0;
    next.stress = eqs.stress(trial);
    if (tangent) *tangent = eqs.tangent(trial, false);
    return next;
  }
  // An increment that starts on the surface (entry t = 0) has the trial's equations.
  const YieldEntry entry = yield_entry(model, increment);
  if (entry.t == 0.0) return plastic_return(model, start, eqs, trial, tangent, estimate);
  if (estimate) {
    estimate->elastic_fraction = entry.t;
    estimate->entry = start;
    estimate->entry.stress = entry.s - entry.p * identity3();
    estimate->entry.plastic_multiplier = 0.0;
  }
  const CamClayReturn entry_eqs(model, increment, model.implicit_alpha(), entry);
  return plastic_return(model, start, entry_eqs, trial, tangent, estimate);
}

namespace {
/// max(‖σ_a − σ_b‖ / max(‖σ_a‖, ‖σ_n‖, 1 Pa), |p_c,a − p_c,b| / p_c,a): the relative distance of two
/// results of one sub-increment from `start` (the scale of the Euler-difference estimate).
double relative_difference(const State& a, const State& b, const State& start) {
  const Mat3 d = a.stress - b.stress;
  const double scale =
      std::max({std::sqrt(ddot(a.stress, a.stress)), std::sqrt(ddot(start.stress, start.stress)), 1.0});
  return std::max(std::sqrt(ddot(d, d)) / scale, std::abs(a.pc - b.pc) / a.pc);
}

/// Local extrapolation of an accepted doubling that ends on the surface: the midpoint's local error
/// C h³ + O(h⁴) gives X(halves) − X(h) = −¾ C h³, so X(halves) + (X(halves) − X(h))/3 cancels the
/// h³ term (Richardson), leaving O(h⁴) for (σ, p_c). The extrapolated stress is off the surface by
/// O(h⁴); the drift correction (drift_correction.h, as after every `substep` substep) puts it back,
/// adding its own multiplier and plastic strain to the halves' accumulated measures. A result the
/// extrapolation would make inadmissible (p_c ≤ 0) keeps the halves.
State extrapolated(const ModifiedCamClay& model, const State& halves, const State& whole) {
  State x = halves;
  x.stress += (halves.stress - whole.stress) / 3.0;
  x.pc += (halves.pc - whole.pc) / 3.0;
  if (!(x.pc > 0.0) || !x.stress.allFinite()) return halves;
  Mat3 drift = Mat3::Zero();
  x.plastic_multiplier += correct_drift(model, x.stress, x.pc, drift);
  accumulate_plastic_strain(x, drift);
  return x;
}
}  // namespace

State implicit_update(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent) {
  const double tolerance = model.implicit_tolerance();
  if (!(tolerance > 0.0)) return implicit_return(model, start, strain_increment, tangent);
  // Error control (Sloan, Abbo & Sheng 2001, with implicit sub-increments) with two estimates:
  //  1. the Euler difference R = ½Δλ‖D:(n(σ_{n+1}) − n(σ_t))‖ of one return (free: the return knows
  //     both ends). It is the local error of first-order Euler, O(h²) in the sub-increment h, while
  //     the accepted midpoint result errs by O(h³): R ≤ tol accepts it at no extra cost (an
  //     increment that needs no split costs one return, as without control), but R > tol would
  //     reject sub-increments that are already accurate (alone it made the control 1.5–3× as dear
  //     as `substep` at equal error), hence the second estimate;
  //  2. when R > tol, step doubling: the same sub-increment as two half returns. With the midpoint's
  //     local error e(h) ≈ C h³, X(h) − X(two halves) = e(h) − 2e(h/2) = ¾ C h³ and the two halves
  //     err by 2 C (h/2)³ = ¼ C h³, so E = ‖X(h) − X(halves)‖ / 3 estimates the error of the halves
  //     (X = σ relative to the stress, and p_c relative), which are accepted when E ≤ tol. What is
  //     kept is their local extrapolation (`extrapolated`: O(h⁴), back on the surface by the drift
  //     correction) when both the whole and the second half end plastic, as `substep` keeps its
  //     modified-Euler result while its estimate is Euler's: the error per tolerance fell 10–30× on
  //     the stiff clay's undrained paths (docs/method/integrators.md, with the cost at equal error).
  // The whole rest of the increment is tried first (its elastic part up to the surface exactly, see
  // below). A rejected sub-increment shrinks by the factor that would meet tol, 0.9 (tol/E)^⅓
  // (0.9 √(tol/R) on the Euler branch, R ∝ h²), in [0.1, 0.9]; an accepted one lets the next grow by
  // the same rule, at most 2×. Sub-increments ≥ kMinFraction of the increment, at most
  // kMaxSubincrements.
  State state = start;
  double done = 0.0, fraction = 1.0, multiplier = 0.0;
  int accepted = 0;
  while (true) {
    const double rest = 1.0 - done;
    const bool last = fraction >= rest;
    if (last) fraction = rest;
    const Mat3 sub = accepted == 0 && last ? strain_increment : Mat3(fraction * strain_increment);
    ReturnEstimate first;
    // The first attempt is always the whole increment from the start: its analytic tangent is the
    // one reported (see below).
    const State whole = implicit_return(model, state, sub, accepted == 0 && last ? tangent : nullptr, &first);
    const double euler = first.euler;
    bool accept = euler <= tolerance || fraction <= kMinFraction;
    if (!accept && first.elastic_fraction > 0.0) {
      // The elastic part up to the surface is exact (the entry search): take it as a sub-increment
      // and control the rest from the surface, so no doubled sub-increment straddles the yield
      // onset, where the midpoint's error is not the smooth C h³ the estimate assumes.
      state = first.entry;
      if (++accepted >= kMaxSubincrements)
        throw IntegrationError("implicit (modified-cam-clay): more than 10000 sub-increments in one increment");
      done += first.elastic_fraction * fraction;
      fraction = last ? 1.0 - done : (1.0 - first.elastic_fraction) * fraction;
      continue;
    }
    State next = whole;
    double factor = euler > 0.0 ? 0.9 * std::sqrt(tolerance / euler) : 2.0;
    if (!accept) {
      const State half = implicit_return(model, state, 0.5 * sub);
      next = implicit_return(model, half, 0.5 * sub);
      const bool ends_plastic = next.plastic_multiplier > 0.0 && whole.plastic_multiplier > 0.0;
      next.plastic_multiplier += half.plastic_multiplier;
      const double estimate = relative_difference(next, whole, state) / 3.0;
      factor = estimate > 0.0 ? 0.9 * std::cbrt(tolerance / estimate) : 2.0;
      accept = estimate <= tolerance;
      if (accept && ends_plastic) next = extrapolated(model, next, whole);
    }
    if (accept) {
      state = next;
      multiplier += next.plastic_multiplier;
      if (last) break;
      if (++accepted >= kMaxSubincrements)
        throw IntegrationError("implicit (modified-cam-clay): more than 10000 sub-increments in one increment");
      done += fraction;
      fraction = std::max(fraction * std::min(factor, 2.0), kMinFraction);
    } else {
      fraction = std::max(fraction * std::clamp(factor, 0.1, 0.9), kMinFraction);
    }
  }
  state.plastic_multiplier = multiplier;
  // The tangent reported for a split increment is the analytic one of the single return over the
  // whole increment (computed by the first attempt), not the derivative of the composed returns: it
  // is what the mixed-control driver's Newton needs (a search direction; the result is converged on
  // the residual whatever the tangent), as `substep` reports it. The exact derivative by central
  // differences of the composed returns cost 12 composed runs per Newton iteration, which made the
  // drained driver with control ~20× dearer than without; the single-return tangent costs nothing.
  return state;
}

}  // namespace soilsph
