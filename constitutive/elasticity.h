#pragma once
/// @file
/// Isotropic elasticity, constant or pressure-dependent.
///  - constant:           K = E / (3(1−2ν)),  G = E / (2(1+ν));
///  - pressure-dependent: K = (1+e0) p / κ with constant ν, so G = 3K(1−2ν) / (2(1+ν)) (the Cam-Clay
///    swelling line ε_v^e = κ/(1+e0) · ln(p/p_i)). As p → 0 the stiffness would vanish, so K uses
///    max(p, p_floor): below the floor the response is linear with K(p_floor). The floor is the
///    material key `elastic_pressure_floor` (Pa).
#include "constitutive/enum_names.h"
#include "constitutive/tensor.h"

namespace soilsph {

/// Bulk and shear moduli at one state.
struct Moduli {
  double K;
  double G;
  /// D : ε = K tr(ε) I + 2G dev(ε)
  Mat3 stiffness(const Mat3& eps) const {
    return K * eps.trace() * Mat3::Identity() + 2.0 * G * deviator(eps);
  }
  /// C : σ = tr(σ)/(9K) I + dev(σ)/(2G), the inverse of stiffness().
  Mat3 compliance(const Mat3& sigma) const {
    return sigma.trace() / (9.0 * K) * Mat3::Identity() + deviator(sigma) / (2.0 * G);
  }
};

/// Everything an implicit return needs about one elastic volume change dεv from p.
struct ElasticVolumeStep {
  double p;             ///< pressure_after(p, dεv)
  Moduli tangent;       ///< at(pressure after)
  Moduli secant;        ///< secant(p, dεv)
  Moduli secant_slope;  ///< d/d(dεv) of the secant moduli (what an implicit return with the secant G needs)
};

class Elasticity {
 public:
  enum class Kind { Constant, PressureDependent };

  static Elasticity constant(double young_modulus, double poisson_ratio);
  static Elasticity pressure_dependent(double swelling_index, double initial_void_ratio, double poisson_ratio,
                                       double pressure_floor);

  Kind kind() const { return kind_; }
  double poisson_ratio() const { return nu_; }

  /// Tangent moduli at mean pressure p (compression-positive).
  Moduli at(double p) const {
    if (kind_ == Kind::Constant) return constant_;
    const double K = std::max(p, p_floor_) / kappa_star_;
    return {K, shear_from_bulk(K)};
  }

  /// Mean pressure after an elastic volumetric strain dεv (compression-positive) from p, integrating
  /// dp/dε_v = K(p) exactly (exponential above the floor, linear below it).
  double pressure_after(double p, double d_eps_v) const { return p + pressure_change(p, d_eps_v); }
  /// pressure_after(p, dεv) − p, computed without cancellation.
  double pressure_change(double p, double d_eps_v) const;

  /// Secant moduli over an elastic volumetric strain dεv from p: K = Δp/Δε_v (the tangent for
  /// Δε_v → 0), G from K and ν. Equal to at(p) for constant elasticity.
  Moduli secant(double p, double d_eps_v) const;
  /// The pressure after dεv, the tangent moduli there, the secant moduli and their slope, with one
  /// exponential on the swelling line (the implicit return's inner loop). Constant elasticity inline:
  /// the call was 3 % of the MCC collapse's instructions.
  ElasticVolumeStep volume_step(double p, double d_eps_v) const {
    if (kind_ == Kind::Constant) return {p + constant_.K * d_eps_v, constant_, constant_, {0.0, 0.0}};
    return pressure_dependent_volume_step(p, d_eps_v);
  }

 private:
  ElasticVolumeStep pressure_dependent_volume_step(double p, double d_eps_v) const;
  double shear_from_bulk(double K) const { return 1.5 * K * (1.0 - 2.0 * nu_) / (1.0 + nu_); }

  Kind kind_ = Kind::Constant;
  double nu_ = 0.0;
  Moduli constant_{0.0, 0.0};
  double kappa_star_ = 0.0;  ///< κ / (1+e0)
  double p_floor_ = 0.0;
};

/// The input names of the kinds (Modified Cam-Clay's `elasticity` key).
inline constexpr auto kElasticityKindTable = enum_table<Elasticity::Kind>({
    {Elasticity::Kind::Constant, "constant"},
    {Elasticity::Kind::PressureDependent, "pressure-dependent"},
});

}  // namespace soilsph
