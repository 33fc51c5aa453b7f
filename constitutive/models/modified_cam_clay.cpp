#include "constitutive/models/modified_cam_clay.h"

#include <numbers>
#include <sstream>
#include <stdexcept>

#include "constitutive/derived_constants.h"
#include "constitutive/integrators/integrate.h"
#include "constitutive/material_limits.h"
#include "constitutive/tangent.h"

namespace soilsph {

template <class Io>
void ModifiedCamClayParams::fields(const Io& io) {
  io.number("density", density, Range::positive(), "kg/m^3");
  io.when(elasticity == Elasticity::Kind::Constant)
      .number("young_modulus", young_modulus, limits::young_modulus_range(), "Pa");
  io.number("poisson_ratio", poisson_ratio, Range::open(-1.0, 0.5));
  // From 1 degree: below it M < 0.035 and the ellipse degenerates into the p axis (at 1e-299
  // degrees M^2 underflows and returns end above p_c); no soil's critical state is that smooth.
  io.number("friction_angle", friction_angle, Range::closed_open(1.0, 90.0), "degrees");
  io.number("compression_index", compression_index, Range::positive());
  io.number("swelling_index", swelling_index, Range::open(0.0, compression_index));
  io.number("initial_void_ratio", initial_void_ratio, Range::positive());
  io.choice_or("elasticity", elasticity, kElasticityKindTable);
  io.when(elasticity == Elasticity::Kind::PressureDependent)
      .number_or("elastic_pressure_floor", elastic_pressure_floor, limits::stress_range(), "Pa");
  io.choice_or("integrator", integrator, kIntegratorTable);
  io.number_or("substep_tolerance", substep_tolerance, kSubstepToleranceRange);
  io.number_or("implicit_alpha", implicit_alpha, Range::closed(0.5, 1.0));
  // Below 1e-12 (as substep_tolerance) the error control cannot be met in double precision and
  // splits every plastic update into its 10 000 sub-increments (an input-fuzzer finding: 1e-30).
  io.number_or("implicit_tolerance", implicit_tolerance, Range::zero_or_closed(1e-12, 1e-2));
  io.number_or("minimum_preconsolidation", minimum_preconsolidation, Range::closed(0.0, limits::kMaxStress),
               "Pa", Listed::WhenSet);
  io.choice_or("hardening_volume", hardening_volume, kHardeningVolumeTable, Listed::WhenSet);
  io.number_or("viscoplastic_relaxation_time", viscoplastic_relaxation_time, limits::relaxation_time_range(),
               "s", Listed::WhenSet);
}
template void ModifiedCamClayParams::fields(const FieldDescriber&);
template void ModifiedCamClayParams::fields(const KeyLister&);

ModifiedCamClayParams ModifiedCamClayParams::read(const TableReader& t) {
  // `elasticity` decides whether young_modulus applies, which comes before it in the list: it is taken
  // first, and a bad value is reported at its place in the list.
  ModifiedCamClayParams params;
  try {
    FieldReader(t).choice_or("elasticity", params.elasticity, kElasticityKindTable);
  } catch (const ParameterError&) {
  }
  return read_fields(t, params);
}

namespace {
Elasticity make_elasticity(const ModifiedCamClayParams& p) {
  if (p.elasticity == Elasticity::Kind::Constant)
    return Elasticity::constant(p.young_modulus, p.poisson_ratio);
  return Elasticity::pressure_dependent(p.swelling_index, p.initial_void_ratio, p.poisson_ratio,
                                        p.elastic_pressure_floor);
}
}  // namespace

ModifiedCamClay::ModifiedCamClay(const Params& params)
    : params_(validated(params, kName)),
      elasticity_(make_elasticity(params)),
      theta_((1.0 + params.initial_void_ratio) / (params.compression_index - params.swelling_index)) {
  const double sin_phi = std::sin(params.friction_angle * std::numbers::pi / 180.0);
  M_ = 6.0 * sin_phi / (3.0 - sin_phi);  // eq 26
  require_derived(kName, "friction_angle", params.friction_angle, "M = 6 sin(phi)/(3 - sin(phi)) (eq 26)", M_,
                  "");
  require_derived(kName, "initial_void_ratio", params.initial_void_ratio, "(1+e0)/(lambda-kappa) (eq 27)",
                  theta_, "");
  if (params.elasticity == Elasticity::Kind::Constant) {
    require_constant_moduli(kName, params.young_modulus, elasticity_);
    return;
  }
  // The smallest pressure-dependent moduli, at the floor: K = p_floor (1+e0)/κ. With p_floor ≤ 1e12 Pa
  // and a finite θ (above), an infinite K comes from a κ that is (nearly) subnormal: it is blamed.
  const Moduli D = elasticity_.at(0.0);
  require_derived(kName, "swelling_index", params.swelling_index,
                  "K = p_floor (1+e0)/kappa at the elastic_pressure_floor", D.K, "Pa");
  require_derived(kName, "elastic_pressure_floor", params.elastic_pressure_floor, "G = 3K(1-2 nu)/(2(1+nu))",
                  D.G, "Pa");
}

double ModifiedCamClay::yield(const Mat3& sigma, double pc) const {
  const double p = mean_pressure(sigma);
  return M_ * M_ * p * (p - pc) + 3.0 * second_deviatoric_invariant(sigma);
}

double ModifiedCamClay::normalized_yield(const Mat3& sigma, double pc) const {
  return yield(sigma, pc) / std::max(M_ * M_ * pc * pc, 1e-300);
}

Mat3 ModifiedCamClay::yield_gradient(const Mat3& sigma, double pc) const {
  const double p = mean_pressure(sigma);
  return -M_ * M_ * (2.0 * p - pc) / 3.0 * Mat3::Identity() + 3.0 * deviator(sigma);
}

double ModifiedCamClay::hardening_modulus(const Mat3& sigma, double pc) const {
  // The flow's plastic volume has the sign of ∂f/∂p = M²(2p − p_c): compaction where 2p > p_c.
  const double p = mean_pressure(sigma), compaction = 2.0 * p - pc;
  return hardening_exponent_at(pc, compaction) * p * pc * M_ * M_ * M_ * M_ * compaction;
}

double ModifiedCamClay::harden(double pc, const Mat3& d_plastic_strain) const {
  return hardened(pc, volumetric_strain(d_plastic_strain));
}

double ModifiedCamClay::initial_preconsolidation(const Mat3& sigma, double ocr, double floor) const {
  const double p = mean_pressure(sigma), q = deviatoric_stress(sigma);
  const double on_surface = p > 0.0 ? p + q * q / (M_ * M_ * p) : 0.0;
  return std::max({ocr * on_surface, floor, params_.minimum_preconsolidation});
}

StateMarks ModifiedCamClay::marks(const State& s) const {
  const double p = mean_pressure(s.stress);
  StateMarks m;
  m.near_zero_pressure = p < 0.01 * s.pc;
  m.near_critical_state =
      s.plastic_multiplier > 0.0 && std::abs(deviatoric_stress(s.stress) / (M_ * p) - 1.0) < 0.05;
  return m;
}

std::string ModifiedCamClay::describe_constants() const {
  std::ostringstream out;
  out << "  M = " << M_ << " (eq 26), (1+e0)/(lambda-kappa) = " << theta_ << '\n';
  return out.str();
}

Mat3 ModifiedCamClay::correct(const Mat3& sigma, double pc) const {
  if (yield(sigma, pc) <= 0.0) return sigma;
  const double p = mean_pressure(sigma);
  const Mat3 s = deviator(sigma);
  const double q = std::sqrt(1.5 * ddot(s, s));
  const double half = 0.5 * pc;
  const double t = M_ * half / std::sqrt(M_ * M_ * (p - half) * (p - half) + q * q);
  // q' = t q, so the deviator scales by t; p' = p_c/2 + t (p − p_c/2).
  return t * s + isotropic_stress(half + t * (p - half));
}

ModifiedCamClay ModifiedCamClay::hardening_at(double volumetric_strain) const {
  ModifiedCamClay at = *this;
  if (!hardens_with_current_volume()) return at;
  const double v = (1.0 + params_.initial_void_ratio) * (1.0 + volumetric_strain);  // v − v0 = v0 ε_v
  if (!(v > 0.0))
    throw std::runtime_error(
        "modified-cam-clay: the specific volume v = (1+e0)(1 + eps_v) = " + format_number(v) +
        " is not positive (hardening_volume = \"current\", eps_v = " + format_number(volumetric_strain) +
        ")");
  at.theta_ = v / (params_.compression_index - params_.swelling_index);
  return at;
}

State ModifiedCamClay::update(const State& state, const Mat3& strain_increment,
                              const Mat3& spin_increment) const {
  if (!hardens_with_current_volume()) return integrate(*this, state, strain_increment, spin_increment);
  // The volume at the increment's end, known before the return: one exponent for the whole
  // increment, exact as the increment shrinks.
  const double volumetric_strain = state.volumetric_strain + strain_increment.trace();
  State next = integrate(hardening_at(volumetric_strain), state, strain_increment, spin_increment);
  next.volumetric_strain = volumetric_strain;
  return next;
}

Mat6 ModifiedCamClay::consistent_tangent(const State& state, const Mat3& strain_increment) const {
  // `substep` converges to the exact rate solution, whose tangent the implicit one approximates to
  // first order in the increment: one update for a Newton tangent instead of the 12 of differences.
  // The error-controlled `implicit` (implicit_tolerance > 0) reports the same single-return tangent
  // (implicit_update), so it is taken here without running the sub-increments: they cost the
  // mixed-control driver a third of its updates and left the tangent unchanged.
  if (integrator() == Integrator::Explicit) return finite_difference_tangent(*this, state, strain_increment);
  Mat6 tangent;
  implicit_return(hardening_at(state.volumetric_strain + strain_increment.trace()), state, strain_increment,
                  &tangent);
  return tangent;
}

}  // namespace soilsph
