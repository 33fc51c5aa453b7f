#pragma once
/// @file
/// Modified Cam-Clay (paper §3.2.3), associated flow, isotropic hardening with the plastic volume.
///   yield      f = M²p² + q² − M² p p_c                                    (eq 24)
///   slope      M = 6 sinφ / (3 − sinφ)  (triaxial compression, used at every Lode angle)  (eq 26)
///   hardening  p_c = p_c0 exp[(1+e0)/(λ−κ) · ε_v^p], ε_v^p compression-positive   (eq 27)
///              softening no further than p_c,min (`minimum_preconsolidation`, default 0: none);
///              with hardening_volume = "current", dp_c/p_c = v/(λ−κ) dε_v^p with the current
///              specific volume v = (1+e0)(1 + ε_v) (ε_v the total volumetric strain, tension-positive)
/// The paper writes eq 27 for compression-positive ε_v^p while its stresses are tension-positive
/// (paper-notes): the flow rule's plastic volume is negated before it enters the hardening law.
#include <algorithm>
#include <cmath>
#include <string>

#include "constitutive/elasticity.h"
#include "constitutive/failure_line.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/parameters.h"
#include "constitutive/state.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// The specific volume v in the hardening law's exponent v/(λ−κ) (eq 27).
enum class HardeningVolume {
  Initial,  ///< v0 = 1 + e0 throughout: eq 27 as printed
  /// v = v0 (1 + ε_v) from the total volumetric strain ε_v (tension-positive) since the initial
  /// state, the linear kinematic relation v − v0 = v0 ε_V of OpenGeoSys's ModCamClay; taken at each
  /// increment's end (the strain there is known before the return), so every integrator, the CVODE
  /// reference (at each instant) and the SPH solver (through the model's update) follow it.
  Current,
};
inline constexpr auto kHardeningVolumeTable = enum_table<HardeningVolume>({
    {HardeningVolume::Initial, "initial"},
    {HardeningVolume::Current, "current"},
});

/// The parameters, with the defaults of an input file: a struct built in code runs as the same TOML
/// with the required keys given (the model's constructor checks every range).
struct ModifiedCamClayParams {
  /// Input default: the second-order implicit return reaches an error ≤ 1e-4 cheapest on the drained
  /// and oedometer work-precision paths, 3-9× cheaper than `substep` at its default tolerance, with a
  /// cost per update that does not grow with the increment (docs/method/integrators.md).
  static constexpr Integrator kDefaultIntegrator = Integrator::Implicit;
  static constexpr double kDefaultImplicitAlpha = 0.5;
  double density = 0.0;             ///< kg/m³ (required)
  double poisson_ratio = 0.0;       ///< − (required)
  double friction_angle = 0.0;      ///< φ, degrees (gives M, eq 26) (required)
  double compression_index = 0.0;   ///< λ, slope of the NCL in e–ln p (required)
  double swelling_index = 0.0;      ///< κ, slope of the swelling line in e–ln p (required)
  double initial_void_ratio = 0.0;  ///< e0 (required)
  /// "constant" (E, ν) or "pressure-dependent" (K = (1+e0)p/κ)
  Elasticity::Kind elasticity = Elasticity::Kind::PressureDependent;
  double young_modulus = 0.0;             ///< Pa, constant elasticity only (then required)
  double elastic_pressure_floor = 1.0e3;  ///< Pa, pressure-dependent elasticity only
  Integrator integrator = kDefaultIntegrator;
  double substep_tolerance = kDefaultSubstepTolerance;  ///< `substep`: relative stress-error tolerance
  /// `implicit`: generalised-midpoint parameter α of the flow rule, ½ (midpoint, second order) to 1
  /// (backward Euler, first order).
  double implicit_alpha = kDefaultImplicitAlpha;
  /// `implicit`: local error tolerance of the error-controlled sub-incrementation (relative stress
  /// change, see implicit_update in implicit_cam_clay.h); 0 (the default) is one return per increment.
  double implicit_tolerance = 0.0;
  /// Pa: the smallest p_c that softening reaches, the loosest state of the soil (its largest void
  /// ratio on the normal compression line, e = e_N − λ ln p_c,min); 0 (the default): none, eq 27 as
  /// printed. Compression still hardens from it. See hardening_exponent_at().
  double minimum_preconsolidation = 0.0;
  /// The specific volume of the hardening law: "initial" (default, eq 27) or "current".
  HardeningVolume hardening_volume = HardeningVolume::Initial;
  /// τ, s: Duvaut–Lions relaxation time in the SPH solver (constitutive/viscoplastic_relaxation.h); 0:
  /// rate-independent, as the paper.
  double viscoplastic_relaxation_time = 0.0;

  static ModifiedCamClayParams read(const TableReader& table);
  /// Every key with its range and default, read, checked, described or listed by `io`
  /// (FieldReader, FieldChecker, FieldDescriber, KeyLister), in the order results list them.
  template <class Io>
  void fields(const Io& io);
};

class ModifiedCamClay {
 public:
  using Params = ModifiedCamClayParams;
  static constexpr std::string_view kName = "modified-cam-clay";

  explicit ModifiedCamClay(const Params& params);

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }
  Integrator integrator() const { return params_.integrator; }
  double substep_tolerance() const { return params_.substep_tolerance; }
  double implicit_alpha() const { return params_.implicit_alpha; }
  double implicit_tolerance() const { return params_.implicit_tolerance; }
  double M() const { return M_; }
  /// (1+e0)/(λ−κ): the hardening exponent per unit plastic volumetric strain (eq 27); v/(λ−κ) with
  /// the current specific volume in the model hardening_at() returns.
  double hardening_exponent() const { return theta_; }
  /// Whether the hardening follows the current specific volume (hardening_volume = "current").
  bool hardens_with_current_volume() const { return params_.hardening_volume == HardeningVolume::Current; }
  /// The model whose hardening exponent is v/(λ−κ) at the total volumetric strain `volumetric_strain`
  /// (tension-positive), v = (1+e0)(1 + ε_v); itself when the hardening uses the initial volume.
  /// Throws std::runtime_error where v ≤ 0 (a compression beyond the whole volume).
  ModifiedCamClay hardening_at(double volumetric_strain) const;
  /// p_c,min: softening stops there (0: never).
  double minimum_preconsolidation() const { return params_.minimum_preconsolidation; }
  /// The exponent that applies at p_c for a plastic volume change of the sign of `compaction`
  /// (compression-positive): θ, or 0 where softening (compaction < 0) has reached p_c,min. The dry
  /// side's softening then stops: the surface keeps the size of the loosest state, and flow there is
  /// perfectly plastic. Without the bound a free-surface particle softens to p_c ~ 1e-11 Pa ("dust")
  /// and must then compact by a plastic volume ln(p/p_c)/θ ≈ 1 before it carries 100 Pa again: in the SPH
  /// collapse of a soft overconsolidated column such grains fell onto the toe, were compressed to
  /// 1.6–1.9× their density and pushed into the floor; a bound of 10 Pa keeps them out
  /// (docs/validation/resolution.md).
  double hardening_exponent_at(double pc, double compaction) const {
    return compaction < 0.0 && pc <= params_.minimum_preconsolidation ? 0.0 : theta_;
  }
  /// p_c after a plastic volume change ε_v^p (compression-positive) from p_c: eq 27 exact, with
  /// softening stopped at p_c,min (a start already below it softens no further).
  double hardened(double pc, double plastic_volume) const {
    const double exact = pc * std::exp(theta_ * plastic_volume);
    return std::max(exact, std::min(pc, params_.minimum_preconsolidation));
  }

  /// f(σ, p_c) (eq 24), in Pa².
  double yield(const Mat3& sigma, double pc) const;
  /// f / (M p_c)², dimensionless.
  double normalized_yield(const Mat3& sigma, double pc) const;
  /// ∂f/∂σ = −M²(2p − p_c) I/3 + 3s.
  Mat3 yield_gradient(const Mat3& sigma, double pc) const;
  /// Associated flow: ∂g/∂σ = ∂f/∂σ.
  Mat3 flow_direction(const Mat3& sigma, double pc) const { return yield_gradient(sigma, pc); }
  /// H = −∂f/∂p_c · ∂p_c/∂λ = (1+e0)/(λ−κ) · p p_c M⁴ (2p − p_c): the hardening term of the
  /// consistency condition (denominator of eq 29).
  double hardening_modulus(const Mat3& sigma, double pc) const;
  /// p_c after a plastic strain increment, eq 27 exact over the increment.
  double harden(double pc, const Mat3& d_plastic_strain) const;
  /// p_c is the hardening variable: an OCR sets it.
  static constexpr bool kHasPreconsolidation = true;
  /// The initial p_c at effective stress σ with overconsolidation ratio OCR:
  ///   p_c = max(OCR · (p + q²/(M² p)), floor, p_c,min),
  /// OCR times the p_c of the ellipse through (p, q) (eq 24), OCR · p on an isotropic state; 0
  /// before the floor where p ≤ 0 (a free surface). One formula for the point programmes and the
  /// SPH column (whose [initial] preconsolidation_floor keeps the top from having no strength).
  double initial_preconsolidation(const Mat3& sigma, double ocr, double floor = 0.0) const;
  /// ṗ_c of the rate equations (CVODE reference) for plastic flow λ̇ n_g: eq 27 in rate form,
  /// (1+e0)/(λ−κ) · p_c · (−tr ε̇^p) with the compression-positive plastic volume −tr ε̇^p.
  double hardening_rate(const Mat3& /*sigma*/, double pc, double lambda_dot, const Mat3& n_g) const {
    const double compaction = -lambda_dot * n_g.trace();
    return hardening_exponent_at(pc, compaction) * pc * compaction;
  }
  /// The stress test's marks: p' < 0.01 p_c, and a plastic state with |q/(M p') − 1| < 0.05.
  StateMarks marks(const State& s) const;
  /// The derived constants, one "  name = value" line each (`soilsph material`).
  std::string describe_constants() const;
  /// The critical-state line q = M p′ (eq 26).
  FailureLine triaxial_failure_line() const { return {M_, 0.0}; }
  /// The paper's correction (eq 34–35) done as its text describes: move (p, q) along the line to the
  /// ellipse's centre (p_c/2, 0) until it meets the surface; p_c is kept. The printed β, θ of eq 35
  /// are not that point (paper-notes), so the intersection is derived here:
  ///   (p', q') = (p_c/2, 0) + t (p − p_c/2, q),  t = (M p_c/2) / √(M²(p − p_c/2)² + q²),
  /// which solves M²(p' − p_c/2)² + q'² = (M p_c/2)², i.e. f(p', q', p_c) = 0.
  Mat3 correct(const Mat3& sigma, double pc) const;

  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment) const;
  /// ∂σ/∂Δε of update() without spin: central differences for `explicit`; the analytic consistent
  /// tangent of `implicit` for `implicit` and (as a close approximation of its own) for `substep`.
  Mat6 consistent_tangent(const State& state, const Mat3& strain_increment) const;

 private:
  Params params_;
  Elasticity elasticity_;
  double M_;
  double theta_;
};

}  // namespace soilsph
