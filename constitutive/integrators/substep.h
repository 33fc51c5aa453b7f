#pragma once
/// @file
/// `substep`: explicit modified-Euler substepping with local error control, after Sloan, Abbo & Sheng
/// (2001), "Refined explicit integration of elastoplastic models with automatic error control",
/// Eng. Computations 18(1/2):121–154. One increment Δε is integrated as follows:
///  1. Elastic trial σ_n + D_sec:Δε with the secant moduli over the increment (Elasticity::secant:
///     exact for the pressure-dependent swelling line). Inside the surface (f ≤ FTOL): done.
///  2. Elastic fraction α: for an elastic start, Pegasus iteration on f(σ_n + D_sec(α):αΔε) = 0; for a
///     start on the surface, the loading test n_f : D:Δε ≥ −LTOL ‖n_f‖‖D:Δε‖, and for elastic-plastic
///     unloading a scan of [0, 1] for the point where f < 0 followed by Pegasus on the far crossing.
///  3. The plastic part (1−α)Δε in pseudo-time T ∈ [0, 1] by modified-Euler substeps ΔT:
///       Δσ₁ = D(σ):(dε − dλ₁ n_g(σ)),  Δσ₂ = the same at (σ + Δσ₁, p_c1),  σ ← σ + ½(Δσ₁ + Δσ₂),
///     dλ = n_f : D : dε / (n_f : D : n_g + H) (the rate form of eq 22/29) with the tangent moduli D
///     at the stage's stress. The local error R = ½‖Δσ₂ − Δσ₁‖/‖σ‖ (and the same for p_c) is compared
///     with the tolerance STOL (material key `substep_tolerance`); the step is accepted when R ≤ STOL
///     and the next step is ΔT ← q ΔT with q = 0.9 √(STOL/R) ∈ [0.1, 1.1] (q ≤ 1 right after a rejection).
///  4. Drift correction after each accepted substep (Sloan's consistent correction
///     σ ← σ − δλ D:n_g, p_c ← p_c(δλ n_g), δλ = f/(n_f:D:n_g + H); the normal correction
///     σ ← σ − f n_f/(n_f:n_f) if that does not reduce |f|; the model's own geometric correction as a
///     last resort; drift_correction.h), so every substep ends on the surface within FTOL.
/// Too many substeps, or a step below the minimum size with the error still above STOL, hands the rest
/// of the increment to the model's closest-point projection (`implicit_update`; D-P and MCC have one:
/// needed at the D-P apex, where the error does not fall with the step); a model without one throws
/// IntegrationError. No path returns a NaN.
/// A model with a tension cut-off (`beyond_tension_cutoff(trial)`, the D-P apex) returns its
/// `correct()` state when the elastic trial lies past the cut-off: see docs/method/integrators.md for
/// why that is exact for D-P with ψ = 0 and why no explicit substep can resolve the apex kink anyway.
#include <cmath>
#include <limits>
#include <string>

#include "constitutive/integrators/drift_correction.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/state.h"

namespace soilsph {

namespace substep_detail {
/// |normalized f| accepted as "on the surface" (Sloan's FTOL).
inline constexpr double kYieldTolerance = kSurfaceTolerance;
/// Loading test tolerance on the cosine between n_f and the elastic stress increment (Sloan's LTOL).
inline constexpr double kLoadingTolerance = 1e-6;
inline constexpr double kMinStepFraction = 1e-9;  ///< smallest pseudo-time substep ΔT
/// Substeps allowed per increment at STOL = 1e-6, scaled by √(1e-6/STOL) for tighter tolerances (the
/// modified-Euler substep count grows like STOL^-1/2); beyond: the rest by the implicit return (or failure).
/// 2000 covers a 0.1 strain increment of the Table 1 clay at 1e-6 (about 1000 substeps).
inline constexpr double kMaxSubstepsAtMicro = 2000.0;
inline double max_substeps(double tolerance) {
  return kMaxSubstepsAtMicro * std::max(1.0, std::sqrt(1e-6 / tolerance));
}
inline constexpr int kMaxPegasusIterations = 100;
inline constexpr int kUnloadingScan =
    16;  ///< subdivisions searched for the elastic part of an unloading step
/// Stresses below this norm (Pa) are compared absolutely in the error estimate (a stress-free state).
inline constexpr double kStressFloor = 1.0;

/// One forward-Euler evaluation of the plastic rate over a strain increment.
struct PlasticRate {
  Mat3 d_stress;
  Mat3 d_plastic_strain;
  double pc;  ///< p_c at the end of the evaluation
  double d_lambda;
};

template <class Model>
PlasticRate plastic_rate(const Model& model, const Mat3& sigma, double pc, const Mat3& d_eps) {
  const Moduli D = model.elasticity().at(mean_pressure(sigma));
  const Mat3 elastic = D.stiffness(d_eps);
  const Mat3 n_f = model.yield_gradient(sigma, pc);
  const Mat3 n_g = model.flow_direction(sigma, pc);
  const Mat3 D_ng = D.stiffness(n_g);
  const double denominator = ddot(n_f, D_ng) + model.hardening_modulus(sigma, pc);
  const double numerator = ddot(n_f, elastic);
  const double d_lambda = (numerator > 0.0 && denominator > 0.0) ? numerator / denominator : 0.0;
  const Mat3 d_plastic = d_lambda * n_g;
  return {elastic - d_lambda * D_ng, d_plastic, model.harden(pc, d_plastic), d_lambda};
}

/// Pegasus (modified regula falsi) root of g on [a, b] with g(a) < 0 < g(b). Converged when |g| ≤ FTOL
/// or, where g's round-off exceeds FTOL (a surface thinner than the stress's round-off: D-P with
/// φ → 0 at high p), when the bracket has shrunk to the round-off of a fraction of the increment
/// (absolute: the root may be 0, a start on the surface to round-off).
template <class G>
double pegasus(const G& g, double a, double b, double ga, double gb) {
  for (int it = 0; it < kMaxPegasusIterations; ++it) {
    const double c = b - gb * (b - a) / (gb - ga);
    const double gc = g(c);
    if (std::abs(gc) <= kYieldTolerance) return c;
    if (std::abs(b - a) <= 4.0 * std::numeric_limits<double>::epsilon()) return c;
    if (gc * gb < 0.0) {
      a = b;
      ga = gb;
    } else {
      ga *= gb / (gb + gc);
    }
    b = c;
    gb = gc;
  }
  throw IntegrationError("substep: the yield-surface intersection (Pegasus) did not converge");
}

/// What the accepted substeps have accumulated so far: the stress, p_c, the plastic strain and the
/// plastic multiplier.
struct SubstepPath {
  Mat3 sigma;
  double pc;
  Mat3 plastic_strain = Mat3::Zero();
  double multiplier = 0.0;
};

/// The fallback when error control cannot converge: the remaining strain by the model's implicit
/// return from the current substep state, with the accumulated measures of the substeps before it.
template <class Model>
State finish_implicitly(const Model& model, const State& start, const SubstepPath& path, const Mat3& remaining) {
  State mid = start;
  mid.stress = path.sigma;
  mid.pc = path.pc;
  accumulate_plastic_strain(mid, path.plastic_strain);
  State next;
  try {
    next = implicit_update(model, mid, remaining);
  } catch (const IntegrationError& e) {
    // Said as substep's failure: the user chose substep, and the implicit return is its fallback.
    throw IntegrationError(
        "substep: the error control did not converge, and its fallback for the rest of the "
        "increment failed: " +
        std::string(e.what()));
  }
  next.plastic_multiplier = std::max(next.plastic_multiplier + path.multiplier, 0.0);
  return next;
}

/// finish_implicitly where the model has an implicit return; else the error `failure`.
template <class Model>
State finish_implicitly_or_fail(const Model& model, const State& start, const SubstepPath& path,
                                const Mat3& remaining, const std::string& failure) {
  if constexpr (requires { implicit_update(model, start, remaining); })
    return finish_implicitly(model, start, path, remaining);
  else
    throw IntegrationError(failure);
}

/// The state at the cut-off when the elastic trial lies past a model's tension cut-off (the D-P
/// apex): the model's correct() state, with the plastic strain the elastic compliance leaves.
template <class Model>
State tension_cutoff_return(const Model& model, const State& start, const Mat3& trial, const Mat3& strain_increment,
                            double p0) {
  State next = start;
  next.stress = model.correct(trial, start.pc);
  accumulate_plastic_strain(next, strain_increment - model.elasticity().at(p0).compliance(next.stress - start.stress));
  next.plastic_multiplier = std::sqrt(second_deviatoric_invariant(trial)) / model.elasticity().at(p0).G;
  return next;
}

/// Step 2: the elastic fraction α of the increment, on the path σ(α) = `elastic_at(α)` from the
/// start (α = 1 is the trial).
template <class Model, class ElasticAt>
double elastic_fraction(const Model& model, const State& start, const Mat3& trial, const ElasticAt& elastic_at) {
  auto g = [&](double alpha) { return model.normalized_yield(elastic_at(alpha), start.pc); };
  const double f0 = model.normalized_yield(start.stress, start.pc);
  const double f1 = model.normalized_yield(trial, start.pc);
  if (f0 < -kYieldTolerance) return pegasus(g, 0.0, 1.0, f0, f1);
  const Mat3 n_f = model.yield_gradient(start.stress, start.pc);
  const Mat3 d_sigma = trial - start.stress;
  const double cosine = ddot(n_f, d_sigma) / std::max(n_f.norm() * d_sigma.norm(), 1e-300);
  if (cosine < -kLoadingTolerance) {  // elastic-plastic unloading: find where the path is inside
    for (int j = 1; j < kUnloadingScan; ++j) {
      const double a = static_cast<double>(j) / kUnloadingScan;
      const double ga = g(a);
      if (ga < -kYieldTolerance) return pegasus(g, a, 1.0, ga, f1);
    }
  }
  return 0.0;
}

/// One modified-Euler substep over `d_eps` from `path`, and its local error estimate (relative to
/// the stress, not below `stress_scale`; infinite for a non-finite result).
struct ModifiedEulerStep {
  Mat3 sigma;
  double pc;
  Mat3 d_plastic;
  double d_lambda;
  double error;
};

template <class Model>
ModifiedEulerStep modified_euler_step(const Model& model, const SubstepPath& path, const Mat3& d_eps,
                                      double stress_scale) {
  const PlasticRate r1 = plastic_rate(model, path.sigma, path.pc, d_eps);
  const PlasticRate r2 = plastic_rate(model, Mat3(path.sigma + r1.d_stress), r1.pc, d_eps);
  ModifiedEulerStep step{.sigma = path.sigma + 0.5 * (r1.d_stress + r2.d_stress),
                         .pc = 0.0,
                         .d_plastic = 0.5 * (r1.d_plastic_strain + r2.d_plastic_strain),
                         .d_lambda = 0.5 * (r1.d_lambda + r2.d_lambda),
                         .error = 0.0};
  step.pc = model.harden(path.pc, step.d_plastic);
  step.error = 0.5 * (r2.d_stress - r1.d_stress).norm() / std::max(step.sigma.norm(), stress_scale);
  if (path.pc > 0.0)
    step.error = std::max(step.error, 0.5 * std::abs(model.harden(path.pc, r2.d_plastic_strain) - r1.pc) / step.pc);
  // A non-finite rate (Δλ → ∞ where softening cancels the elastic stiffness, p_c overflowing) is
  // a rejected substep: a smaller one is finite.
  if (!std::isfinite(step.error) || !step.sigma.allFinite() || (path.pc > 0.0 && !(step.pc > 0.0)))
    step.error = std::numeric_limits<double>::infinity();
  return step;
}

/// Steps 3 and 4: the plastic part `remaining` of the increment in pseudo-time T ∈ [0, 1] by
/// error-controlled modified-Euler substeps from `path`, each followed by the drift correction.
template <class Model>
State integrate_plastic_part(const Model& model, const State& start, SubstepPath path, const Mat3& remaining) {
  const double tolerance = model.substep_tolerance();
  // Errors relative to the stress, but not below the stress at the start of the increment: near a
  // stress-free D-P apex a purely relative measure would ask for absolute accuracy → 0.
  const double stress_scale = std::max(start.stress.norm(), kStressFloor);
  double T = 0.0, dT = 1.0;
  bool rejected = false;
  int substeps = 0;
  while (T < 1.0) {
    const ModifiedEulerStep step = modified_euler_step(model, path, dT * remaining, stress_scale);
    if (step.error > tolerance && dT <= kMinStepFraction)  // e.g. the D-P apex: the cone is scale-free
      return finish_implicitly_or_fail(model, start, path, (1.0 - T) * remaining,
                                       "substep: substep below the minimum size");
    if (step.error > tolerance) {
      dT = std::max(std::max(0.9 * std::sqrt(tolerance / step.error), 0.1) * dT, kMinStepFraction);
      rejected = true;
      continue;
    }
    path.sigma = step.sigma;
    path.pc = step.pc;
    path.plastic_strain += step.d_plastic;
    path.multiplier += step.d_lambda;
    path.multiplier += correct_drift(model, path.sigma, path.pc, path.plastic_strain);
    T += dT;
    if (++substeps > max_substeps(tolerance) && T < 1.0)
      return finish_implicitly_or_fail(
          model, start, path, (1.0 - T) * remaining,
          "substep: more than " + std::to_string(max_substeps(tolerance)) + " substeps in one increment");
    double growth = step.error > 0.0 ? std::min(0.9 * std::sqrt(tolerance / step.error), 1.1) : 1.1;
    if (rejected) growth = std::min(growth, 1.0);
    rejected = false;
    dT = std::min(std::max(growth * dT, kMinStepFraction), 1.0 - T);
  }
  State next = start;
  next.stress = path.sigma;
  next.pc = path.pc;
  accumulate_plastic_strain(next, path.plastic_strain);
  next.plastic_multiplier = std::max(path.multiplier, 0.0);
  return next;
}
}  // namespace substep_detail

/// One increment by error-controlled modified-Euler substepping (steps 1–4 above). Works for any
/// model that provides what explicit_update() needs plus substep_tolerance().
template <class Model>
State substep_update(const Model& model, const State& start, const Mat3& strain_increment) {
  using namespace substep_detail;
  const double p0 = mean_pressure(start.stress);
  auto elastic_at = [&](double alpha) {
    const Mat3 d_eps = alpha * strain_increment;
    return Mat3(start.stress + model.elasticity().secant(p0, -d_eps.trace()).stiffness(d_eps));
  };
  const Mat3 trial = elastic_at(1.0);
  if (model.normalized_yield(trial, start.pc) <= kYieldTolerance) {
    State next = start;
    next.plastic_multiplier = 0.0;
    next.stress = trial;
    return next;
  }
  if constexpr (requires { model.beyond_tension_cutoff(trial); })
    if (model.beyond_tension_cutoff(trial)) return tension_cutoff_return(model, start, trial, strain_increment, p0);
  const double alpha = elastic_fraction(model, start, trial, elastic_at);
  const SubstepPath path{.sigma = alpha > 0.0 ? elastic_at(alpha) : start.stress, .pc = start.pc};
  return integrate_plastic_part(model, start, path, (1.0 - alpha) * strain_increment);
}

}  // namespace soilsph
