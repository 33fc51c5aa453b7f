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

/// The fallback when error control cannot converge: the remaining strain by the model's implicit
/// return from the current substep state, with the accumulated measures of the substeps before it.
template <class Model>
State finish_implicitly(const Model& model, const State& start, const Mat3& sigma, double pc,
                        const Mat3& plastic_strain, double multiplier, const Mat3& remaining) {
  State mid = start;
  mid.stress = sigma;
  mid.pc = pc;
  accumulate_plastic_strain(mid, plastic_strain);
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
  next.plastic_multiplier = std::max(next.plastic_multiplier + multiplier, 0.0);
  return next;
}
}  // namespace substep_detail

/// One increment by error-controlled modified-Euler substepping. Works for any model that provides
/// what explicit_update() needs plus substep_tolerance().
template <class Model>
State substep_update(const Model& model, const State& start, const Mat3& strain_increment) {
  using namespace substep_detail;
  const double p0 = mean_pressure(start.stress);
  auto elastic_at = [&](double alpha) {
    const Mat3 d_eps = alpha * strain_increment;
    return Mat3(start.stress + model.elasticity().secant(p0, -d_eps.trace()).stiffness(d_eps));
  };
  const Mat3 trial = elastic_at(1.0);
  State next = start;
  next.plastic_multiplier = 0.0;
  if (model.normalized_yield(trial, start.pc) <= kYieldTolerance) {
    next.stress = trial;
    return next;
  }
  if constexpr (requires { model.beyond_tension_cutoff(trial); }) {
    if (model.beyond_tension_cutoff(trial)) {
      next.stress = model.correct(trial, start.pc);
      accumulate_plastic_strain(
          next, strain_increment - model.elasticity().at(p0).compliance(next.stress - start.stress));
      next.plastic_multiplier = std::sqrt(second_deviatoric_invariant(trial)) / model.elasticity().at(p0).G;
      return next;
    }
  }

  // Elastic fraction α of the increment.
  auto g = [&](double alpha) { return model.normalized_yield(elastic_at(alpha), start.pc); };
  const double f0 = model.normalized_yield(start.stress, start.pc);
  const double f1 = model.normalized_yield(trial, start.pc);
  double alpha = 0.0;
  if (f0 < -kYieldTolerance) {
    alpha = pegasus(g, 0.0, 1.0, f0, f1);
  } else {
    const Mat3 n_f = model.yield_gradient(start.stress, start.pc);
    const Mat3 d_sigma = trial - start.stress;
    const double cosine = ddot(n_f, d_sigma) / std::max(n_f.norm() * d_sigma.norm(), 1e-300);
    if (cosine < -kLoadingTolerance) {  // elastic-plastic unloading: find where the path is inside
      for (int j = 1; j < kUnloadingScan; ++j) {
        const double a = static_cast<double>(j) / kUnloadingScan;
        const double ga = g(a);
        if (ga < -kYieldTolerance) {
          alpha = pegasus(g, a, 1.0, ga, f1);
          break;
        }
      }
    }
  }

  Mat3 sigma = alpha > 0.0 ? elastic_at(alpha) : start.stress;
  double pc = start.pc;
  Mat3 plastic_strain = Mat3::Zero();
  double multiplier = 0.0;
  const Mat3 remaining = (1.0 - alpha) * strain_increment;
  const double tolerance = model.substep_tolerance();
  // Errors relative to the stress, but not below the stress at the start of the increment: near a
  // stress-free D-P apex a purely relative measure would ask for absolute accuracy → 0.
  const double stress_scale = std::max(start.stress.norm(), kStressFloor);
  double T = 0.0, dT = 1.0;
  bool rejected = false;
  int substeps = 0;
  while (T < 1.0) {
    const Mat3 d_eps = dT * remaining;
    const PlasticRate r1 = plastic_rate(model, sigma, pc, d_eps);
    const PlasticRate r2 = plastic_rate(model, Mat3(sigma + r1.d_stress), r1.pc, d_eps);
    const Mat3 sigma_new = sigma + 0.5 * (r1.d_stress + r2.d_stress);
    const Mat3 d_plastic = 0.5 * (r1.d_plastic_strain + r2.d_plastic_strain);
    const double pc_new = model.harden(pc, d_plastic);
    double error = 0.5 * (r2.d_stress - r1.d_stress).norm() / std::max(sigma_new.norm(), stress_scale);
    if (pc > 0.0)
      error = std::max(error, 0.5 * std::abs(model.harden(pc, r2.d_plastic_strain) - r1.pc) / pc_new);
    // A non-finite rate (Δλ → ∞ where softening cancels the elastic stiffness, p_c overflowing) is
    // a rejected substep: a smaller one is finite.
    if (!std::isfinite(error) || !sigma_new.allFinite() || (pc > 0.0 && !(pc_new > 0.0)))
      error = std::numeric_limits<double>::infinity();
    if (error > tolerance && dT <= kMinStepFraction) {
      if constexpr (requires { implicit_update(model, start, strain_increment); }) {
        // The error does not decrease with the step (e.g. the D-P apex: the cone is scale-free):
        // the rest of the increment by the model's closest-point projection.
        return finish_implicitly(model, start, sigma, pc, plastic_strain, multiplier, (1.0 - T) * remaining);
      } else {
        throw IntegrationError("substep: substep below the minimum size");
      }
    }
    if (error > tolerance) {
      dT = std::max(std::max(0.9 * std::sqrt(tolerance / error), 0.1) * dT, kMinStepFraction);
      rejected = true;
      continue;
    }
    sigma = sigma_new;
    pc = pc_new;
    plastic_strain += d_plastic;
    multiplier += 0.5 * (r1.d_lambda + r2.d_lambda);
    multiplier += correct_drift(model, sigma, pc, plastic_strain);
    T += dT;
    if (++substeps > max_substeps(tolerance) && T < 1.0) {
      if constexpr (requires { implicit_update(model, start, strain_increment); }) {
        return finish_implicitly(model, start, sigma, pc, plastic_strain, multiplier, (1.0 - T) * remaining);
      } else {
        throw IntegrationError("substep: more than " + std::to_string(max_substeps(tolerance)) +
                               " substeps in one increment");
      }
    }
    double growth = error > 0.0 ? std::min(0.9 * std::sqrt(tolerance / error), 1.1) : 1.1;
    if (rejected) growth = std::min(growth, 1.0);
    rejected = false;
    dT = std::min(std::max(growth * dT, kMinStepFraction), 1.0 - T);
  }
  next.stress = sigma;
  next.pc = pc;
  accumulate_plastic_strain(next, plastic_strain);
  next.plastic_multiplier = std::max(multiplier, 0.0);
  return next;
}

}  // namespace soilsph
