#include "constitutive/elasticity.h"

#include <cmath>

namespace soilsph {

Elasticity Elasticity::constant(double young_modulus, double poisson_ratio) {
  Elasticity e;
  e.kind_ = Kind::Constant;
  e.nu_ = poisson_ratio;
  e.constant_ = {young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)),
                 young_modulus / (2.0 * (1.0 + poisson_ratio))};
  return e;
}

Elasticity Elasticity::pressure_dependent(double swelling_index, double initial_void_ratio,
                                          double poisson_ratio, double pressure_floor) {
  Elasticity e;
  e.kind_ = Kind::PressureDependent;
  e.nu_ = poisson_ratio;
  e.kappa_star_ = swelling_index / (1.0 + initial_void_ratio);
  e.p_floor_ = pressure_floor;
  return e;
}

double Elasticity::pressure_change(double p, double d_eps_v) const {
  if (kind_ == Kind::Constant) return constant_.K * d_eps_v;
  // dp/dε_v = max(p, p_f)/κ*: exponential above the floor, linear (slope p_f/κ*) below it. Each
  // piece is a change, not a difference of pressures, so a small increment keeps its digits.
  const double linear_slope = p_floor_ / kappa_star_;
  if (p >= p_floor_) {
    const double to_floor = kappa_star_ * std::log(p_floor_ / p);  // ≤ 0: strain that brings p to p_f
    if (d_eps_v >= to_floor) return p * std::expm1(d_eps_v / kappa_star_);
    return (p_floor_ - p) + linear_slope * (d_eps_v - to_floor);
  }
  const double to_floor = (p_floor_ - p) / linear_slope;  // > 0
  if (d_eps_v <= to_floor) return linear_slope * d_eps_v;
  return (p_floor_ - p) + p_floor_ * std::expm1((d_eps_v - to_floor) / kappa_star_);
}

namespace {
/// Below this |x| = |dεv|/κ*, a series replaces the difference that cancels.
constexpr double kSeriesLimit = 1e-3;
}  // namespace

Moduli Elasticity::secant(double p, double d_eps_v) const {
  if (kind_ == Kind::Constant || d_eps_v == 0.0) return at(p);
  const double K = pressure_change(p, d_eps_v) / d_eps_v;
  return {K, shear_from_bulk(K)};
}

namespace {
/// φ'(x) for φ(x) = expm1(x)/x: (x eˣ − expm1 x)/x² = 1/2 + x/3 + x²/8 + x³/30 + …
double expm1_ratio_slope(double x, double em1) {
  return std::abs(x) < kSeriesLimit ? 0.5 + x * (1.0 / 3.0 + x * (1.0 / 8.0 + x / 30.0))
                                    : (x * (1.0 + em1) - em1) / (x * x);
}
}  // namespace

ElasticVolumeStep Elasticity::pressure_dependent_volume_step(double p, double d_eps_v) const {
  if (p >= p_floor_) {
    const double x = d_eps_v / kappa_star_, em1 = std::expm1(x);
    const double end = p + p * em1;
    if (end >= p_floor_) {
      // On the swelling line throughout: K_sec = (p/κ*) φ(x), φ = expm1(x)/x, x = dεv/κ*.
      const double K_end = end / kappa_star_;
      const double K_sec = x == 0.0 ? p / kappa_star_ : p / kappa_star_ * (em1 / x);
      const double dK = p / (kappa_star_ * kappa_star_) * expm1_ratio_slope(x, em1);
      return {
          end, {K_end, shear_from_bulk(K_end)}, {K_sec, shear_from_bulk(K_sec)}, {dK, shear_from_bulk(dK)}};
    }
  }
  // At or below the floor for part of the step.
  const double end = pressure_after(p, d_eps_v);
  const Moduli secant_moduli = secant(p, d_eps_v);
  double dK = 0.0;  // below the floor throughout (K_sec = p_f/κ*)
  if ((p < p_floor_) != (end < p_floor_)) {
    // Crossing the floor: dK_sec/dεv = (K_t(end) − K_sec)/dεv, ≥ 0 as K_t is non-decreasing in p.
    dK = std::max((at(end).K - secant_moduli.K) / d_eps_v, 0.0);
  }
  return {end, at(end), secant_moduli, {dK, shear_from_bulk(dK)}};
}

}  // namespace soilsph
