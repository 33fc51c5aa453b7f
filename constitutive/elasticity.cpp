#include "constitutive/elasticity.h"

#include <cmath>

namespace soilsph {

Elasticity Elasticity::constant(double young_modulus, double poisson_ratio) {
  Elasticity e;
  e.kind_ = Kind::Constant;
  e.nu_ = poisson_ratio;
  e.constant_ = {young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio)), young_modulus / (2.0 * (1.0 + poisson_ratio))};
  return e;
}

Elasticity Elasticity::pressure_dependent(double swelling_index, double initial_void_ratio, double poisson_ratio,
                                          double pressure_floor) {
  Elasticity e;
  e.kind_ = Kind::PressureDependent;
  e.nu_ = poisson_ratio;
  e.kappa_star_ = swelling_index / (1.0 + initial_void_ratio);
  e.p_floor_ = pressure_floor;
  return e;
}

double Elasticity::pressure_after(double p, double d_eps_v) const {
  if (kind_ == Kind::Constant) return p + constant_.K * d_eps_v;
  // dp/dε_v = max(p, p_f)/κ*: exponential above the floor, linear (slope p_f/κ*) below it.
  if (p >= p_floor_) {
    const double to_floor = kappa_star_ * std::log(p_floor_ / p);  // ≤ 0: strain that brings p to p_f
    if (d_eps_v >= to_floor) return p * std::exp(d_eps_v / kappa_star_);
    return p_floor_ + p_floor_ / kappa_star_ * (d_eps_v - to_floor);
  }
  const double to_floor = kappa_star_ * (p_floor_ - p) / p_floor_;  // > 0
  if (d_eps_v <= to_floor) return p + p_floor_ / kappa_star_ * d_eps_v;
  return p_floor_ * std::exp((d_eps_v - to_floor) / kappa_star_);
}

Moduli Elasticity::secant(double p, double d_eps_v) const {
  if (kind_ == Kind::Constant) return constant_;
  if (std::abs(d_eps_v) < 1e-14) return at(p);
  const double K = (pressure_after(p, d_eps_v) - p) / d_eps_v;
  return {K, shear_from_bulk(K)};
}

}  // namespace soilsph
