#include "verification/closed_form/cam_clay_compression.h"

#include <cmath>
#include <stdexcept>

#include "verification/closed_form/gsl_numerics.h"

namespace soilsph::verification {

namespace {
/// Relative overshoot of the yield function tolerated on elastic unloading before the closed form
/// (which assumes elastic unloading) is declared invalid.
constexpr double kYieldTolerance = 1e-9;

double g(double eta, double M) {
  return 1.0 + eta * eta / (M * M);
}

/// Depth ln(|η_y − η_K0|/|η − η_K0|) beyond which the state is taken on the K0 line (|η − η_K0| ~ 1e-11).
constexpr double kMaxDepth = 25.0;
}  // namespace

double cam_clay_k0_stress_ratio(const ModifiedCamClay& model) {
  const CamClayConstants c(model);
  if (!c.pressure_dependent) throw std::invalid_argument("MCC K0: needs pressure-dependent elasticity");
  const double b = c.kappa_star / (3.0 * c.shear_to_bulk);
  const double MM = c.M * c.M;
  // N(η) rises from −2λ*/3 at η = 0 to +∞ at η → M: one root.
  return find_root(
      [&](double eta) {
        return b * eta + c.plastic_slope * 2.0 * eta / (MM - eta * eta) - 2.0 * c.lambda_star / 3.0;
      },
      0.0, c.M * (1.0 - 1e-12));
}

CamClayIsotropicCompression::CamClayIsotropicCompression(const ModifiedCamClay& model, double p_initial,
                                                         double ocr)
    : c_(model), p_initial_(p_initial), pc0_(ocr * p_initial) {
  if (ocr < 1.0) throw std::invalid_argument("MCC isotropic closed form: needs OCR >= 1");
}

std::vector<ReferencePoint> CamClayIsotropicCompression::curve(std::span<const double> eps_v) const {
  std::vector<ReferencePoint> out;
  double pc = pc0_;
  for (const double e : eps_v) {
    // Elastic trial from the current plastic volume, then the NCL if the trial passes p_c.
    const double elastic = e - c_.plastic_volume(pc0_, pc);
    double p = c_.pressure_dependent ? p_initial_ * std::exp(elastic / c_.kappa_star)
                                     : p_initial_ + c_.constant_moduli.K * elastic;
    if (p > pc) {
      const auto residual = [&](double s) {
        return c_.elastic_volume(p_initial_, s) + c_.plastic_volume(pc0_, s) - e;
      };
      if (c_.pressure_dependent) {
        p = std::exp((e + c_.kappa_star * std::log(p_initial_) + c_.plastic_slope * std::log(pc0_)) /
                     c_.lambda_star);
      } else {
        double hi = 2.0 * pc;
        while (residual(hi) < 0.0) hi *= 2.0;
        p = find_root(residual, pc, hi);
      }
      pc = p;
    }
    out.push_back({e / 3.0, e, p, 0.0, pc});
  }
  return out;
}

CamClayOedometer::CamClayOedometer(const ModifiedCamClay& model, double p_initial, double ocr)
    : c_(model), p_initial_(p_initial), pc0_(ocr * p_initial) {
  if (!c_.pressure_dependent)
    throw std::invalid_argument("MCC oedometer closed form: needs pressure-dependent elasticity");
  if (ocr < 1.0) throw std::invalid_argument("MCC oedometer closed form: needs OCR >= 1");
  b_ = c_.kappa_star / (3.0 * c_.shear_to_bulk);
  eta_k0_ = cam_clay_k0_stress_ratio(model);
  // Elastic branch: dp' = K dε_a, dq = 2G dε_a ⇒ q = 2c (p' − p'_i) until q² = M² p'(p_c0 − p').
  const double MM = c_.M * c_.M;
  const auto yield = [&](double p) {
    const double q = 2.0 * c_.shear_to_bulk * (p - p_initial_);
    return q * q - MM * p * (pc0_ - p);
  };
  p_yield_ = find_root(yield, p_initial_, pc0_);
  eta_yield_ = 2.0 * c_.shear_to_bulk * (p_yield_ - p_initial_) / p_yield_;
  eps_yield_ = c_.kappa_star * std::log(p_yield_ / p_initial_);
  if (eta_yield_ >= c_.M) throw std::invalid_argument("MCC oedometer closed form: yield on the dry side");
  const double lo = std::min(eta_yield_, eta_k0_), hi = std::max(eta_yield_, eta_k0_);
  for (int i = 0; i <= 100; ++i)
    if (denominator(lo + (hi - lo) * i / 100.0) <= 0.0)
      throw std::invalid_argument("MCC oedometer closed form: the stress-ratio ODE is singular on this path");
}

double CamClayOedometer::numerator(double eta, double offset) const {
  // N(η) − N(η_K0) with offset = η − η_K0, factored so that it has no cancellation next to the fixed point:
  // h(η) − h(η*) = 2(η − η*)(M² + η η*) / ((M² − η²)(M² − η*²)).
  const double MM = c_.M * c_.M, e = eta_k0_;
  return offset * (b_ + 2.0 * c_.plastic_slope * (MM + eta * e) / ((MM - eta * eta) * (MM - e * e)));
}

double CamClayOedometer::denominator(double eta) const {
  const double MM = c_.M * c_.M;
  const double h = 2.0 * eta / (MM - eta * eta), k = 2.0 * eta / (MM + eta * eta);
  return b_ + c_.plastic_slope * k * (h - 2.0 / 3.0);
}

double CamClayOedometer::log_pressure_change(double depth) const {
  return integrate_to_log_depth(
      [&](double e, double offset) { return -denominator(e) / numerator(e, offset); }, eta_yield_, eta_k0_,
      depth);
}

ReferencePoint CamClayOedometer::loading(double eps_a) const {
  const double M = c_.M;
  if (eps_a <= eps_yield_) {
    const double p = p_initial_ * std::exp(eps_a / c_.kappa_star);
    return {eps_a, eps_a, p, 2.0 * c_.shear_to_bulk * (p - p_initial_), pc0_};
  }
  // η approaches η_K0 only as ln p' → ∞. The unknown is the depth d = ln|η_y − η_K0| − ln|η − η_K0|,
  // in which ln p' is well conditioned (solving for η itself would lose digits next to η_K0).
  const auto eta_at = [&](double depth) { return eta_k0_ + (eta_yield_ - eta_k0_) * std::exp(-depth); };
  const auto strain = [&](double depth, double x) {
    return eps_yield_ + c_.lambda_star * x +
           c_.plastic_slope * std::log(g(eta_at(depth), M) / g(eta_yield_, M));
  };
  double depth = kMaxDepth, x = 0.0;
  if (std::abs(eta_yield_ - eta_k0_) < 1e-12 * M) {
    x = (eps_a - strain(depth, 0.0)) / c_.lambda_star;  // already on the K0 line
  } else {
    const auto residual = [&](double d) { return strain(d, log_pressure_change(d)) - eps_a; };
    if (residual(kMaxDepth) >= 0.0) {
      depth = find_root(residual, 0.0, kMaxDepth, 1e-14, 1e-13);
      x = log_pressure_change(depth);
    } else {  // deeper than resolvable: on the K0 line, where dε_a = λ* d ln p'
      x = log_pressure_change(depth);
      x += (eps_a - strain(depth, x)) / c_.lambda_star;
    }
  }
  const double eta = eta_at(depth);
  const double p = p_yield_ * std::exp(x);
  return {eps_a, eps_a, p, eta * p, p * g(eta, M)};
}

std::vector<ReferencePoint> CamClayOedometer::curve(std::span<const double> eps_a) const {
  std::vector<ReferencePoint> out;
  ReferencePoint turn = loading(0.0);  // the state at the largest strain reached so far
  for (const double e : eps_a) {
    if (e >= turn.eps_a) {
      turn = loading(e);
      out.push_back(turn);
      continue;
    }
    const double p = turn.p * std::exp((e - turn.eps_a) / c_.kappa_star);
    const double q = turn.q + 2.0 * c_.shear_to_bulk * (p - turn.p);
    if (c_.M * c_.M * p * (p - turn.p_c) + q * q > kYieldTolerance * c_.M * c_.M * turn.p_c * turn.p_c)
      throw std::domain_error("MCC oedometer closed form: unloading reaches the yield surface");
    out.push_back({e, e, p, q, turn.p_c});
  }
  return out;
}

}  // namespace soilsph::verification
