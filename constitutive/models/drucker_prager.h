#pragma once
/// @file
/// Drucker–Prager elastic–perfectly-plastic model with non-associated flow (paper §3.2.2).
///   yield      f = √J2 + α_φ I1 − k_c                                      (eq 17)
///   constants  α_φ = tanφ / √(9 + 12 tan²φ),  k_c = 3c / √(9 + 12 tan²φ)   (eq 19, plane-strain fit)
///   potential  g = √J2 + α_ψ I1, α_ψ chosen by `plastic_potential` (docs/method/derivations.md):
///              "matched" (default)  α_ψ = tanψ / √(9 + 12 tan²ψ), ψ matched to Mohr–Coulomb as φ is
///              "paper-eq20"         α_ψ = 3 sinψ, the potential as printed (eq 20)
/// Stresses are tension-positive, so I1 < 0 in compression and the cone's apex is at I1 = k_c/α_φ;
/// α_ψ > 0 makes the plastic volume grow (dilate).
#include <cmath>
#include <string>

#include "constitutive/elasticity.h"
#include "constitutive/failure_line.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/models/dilatancy_cutoff.h"
#include "constitutive/models/perfect_plasticity.h"
#include "constitutive/parameters.h"
#include "constitutive/state.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// The plastic potential's I1 coefficient α_ψ as a function of ψ.
enum class PlasticPotential {
  Matched,    ///< α_ψ = tanψ/√(9 + 12 tan²ψ): like α_φ of eq 19; ψ = φ is associated flow
  PaperEq20,  ///< α_ψ = 3 sinψ: eq 20 as printed, to reproduce the paper
};
inline constexpr auto kPlasticPotentialTable = enum_table<PlasticPotential>({
    {PlasticPotential::Matched, "matched"},
    {PlasticPotential::PaperEq20, "paper-eq20"},
});
constexpr std::string_view plastic_potential_name(PlasticPotential potential) {
  return name_of(kPlasticPotentialTable, potential);
}

/// The parameters, with the defaults of an input file: a struct built in code runs as the same TOML
/// with the required keys given (the model's constructor checks every range).
struct DruckerPragerParams : FrictionalParams {
  /// Input default: the closed-form return is the cheapest update (48 ns) and as accurate as any
  /// scheme on the work-precision paths (docs/method/integrators.md).
  static constexpr Integrator kDefaultIntegrator = Integrator::Implicit;
  PlasticPotential plastic_potential = PlasticPotential::Matched;  ///< how α_ψ follows from ψ
  Integrator integrator = kDefaultIntegrator;
  double substep_tolerance = kDefaultSubstepTolerance;  ///< `substep`: relative stress-error tolerance

  static DruckerPragerParams read(const TableReader& table);
  /// Every key with its range and default, read, checked, described or listed by `io`
  /// (FieldReader, FieldChecker, FieldDescriber, KeyLister), in the order results list them.
  template <class Io>
  void fields(const Io& io);
};

class DruckerPrager : public PerfectPlasticity, public DilatancyCutoff<DruckerPrager> {
 public:
  using Params = DruckerPragerParams;
  static constexpr std::string_view kName = "drucker-prager";

  explicit DruckerPrager(const Params& params);

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }
  Integrator integrator() const { return params_.integrator; }
  double substep_tolerance() const { return params_.substep_tolerance; }
  double alpha_phi() const { return alpha_phi_; }
  double k_c() const { return k_c_; }
  /// ∂g/∂I1 of the plastic potential g = √J2 + α_ψ I1, fixed when the model is built.
  double alpha_psi() const { return alpha_psi_; }
  /// I1 at the apex of the cone, k_c/α_φ (paper-notes: eq 31 prints the inverse ratio).
  double apex_first_invariant() const { return k_c_ / alpha_phi_; }

  /// f(σ) (eq 17), in Pa; the hardening argument is unused.
  double yield(const Mat3& sigma, double /*pc*/ = 0.0) const;
  /// f divided by a stress scale of the state, for tolerances that do not depend on units.
  double normalized_yield(const Mat3& sigma, double pc = 0.0) const;
  /// ∂f/∂σ = s/(2√J2) + α_φ I (the deviatoric part is taken as zero at the apex).
  Mat3 yield_gradient(const Mat3& sigma, double /*pc*/ = 0.0) const;
  /// ∂g/∂σ = s/(2√J2) + α_ψ I (eq 20 with α_ψ = 3 sinψ as printed, or the matched α_ψ).
  Mat3 flow_direction(const Mat3& sigma, double /*pc*/ = 0.0) const;
  // Perfect plasticity: hardening_modulus, harden, hardening_rate, initial_preconsolidation and
  // marks (the apex) from PerfectPlasticity.
  /// The derived constants, one "  name = value" line each (`soilsph material`).
  std::string describe_constants() const;
  /// The cone on triaxial compression: √J2 = q/√3 and I1 = −3p′ in f = 0 give
  /// q = 3√3 α_φ p′ + √3 k_c.
  FailureLine triaxial_failure_line() const {
    return {3.0 * std::sqrt(3.0) * alpha_phi_, std::sqrt(3.0) * k_c_};
  }
  /// The paper's stress correction: tension cracking beyond the apex (eq 30–31, apex at
  /// I1 = k_c/α_φ) then scaling of the deviator back to the cone (eq 32–33).
  Mat3 correct(const Mat3& sigma, double pc = 0.0) const;
  /// True when an elastic trial lies past the apex (I1 > k_c/α_φ), where correct() cuts tension off.
  bool beyond_tension_cutoff(const Mat3& trial) const { return trial.trace() > apex_first_invariant(); }

  /// Integrates one increment (strain and spin) with the chosen scheme.
  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment) const;
  /// ∂σ/∂Δε of update() without spin: central differences for `explicit`; the analytic consistent
  /// tangent of `implicit` for `implicit` and (as a close approximation of its own) for `substep`.
  Mat6 consistent_tangent(const State& state, const Mat3& strain_increment) const;

 private:
  Params params_;
  Elasticity elasticity_;
  double alpha_phi_;
  double k_c_;
  double alpha_psi_;
};

}  // namespace soilsph
