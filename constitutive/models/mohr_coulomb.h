#pragma once
/// @file
/// Mohr–Coulomb elastic–perfectly-plastic model with non-associated flow and an optional tension
/// cut-off, in principal stresses σ1 ≥ σ2 ≥ σ3 (tension-positive, so σ3 is the most compressive).
///   yield      f = (σ1 − σ3) + (σ1 + σ3) sinφ − 2c cosφ
///   potential  g = (σ1 − σ3) + (σ1 + σ3) sinψ,   0 ≤ ψ ≤ φ
///   cut-off    f_t = σ1 − T (Rankine, associated), T = `tension_cutoff` (none by default)
/// In compression-positive principal stresses σ'_1 = −σ3 ≥ σ'_3 = −σ1 the yield condition reads
/// σ'_1 − σ'_3 = (σ'_1 + σ'_3) sinφ + 2c cosφ, Coulomb's τ = c + σ' tanφ on the plane of failure
/// (docs/method/derivations.md). Without a cut-off the pyramid's apex is the isotropic
/// tension σ1 = σ2 = σ3 = c cotφ. The implicit return works in principal stresses with the main
/// plane, the two edges and the apex (integrators/implicit_mohr_coulomb.h).
#include <array>
#include <limits>
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

/// The parameters, with the defaults of an input file (the constructor checks every range).
struct MohrCoulombParams : FrictionalParams {
  /// Input default: the principal-stress return is exact for this piecewise-linear model while the
  /// flowing planes do not change inside an increment (docs/method/integrators.md).
  static constexpr Integrator kDefaultIntegrator = Integrator::Implicit;
  static constexpr double kNoTensionCutoff = std::numeric_limits<double>::infinity();
  double tension_cutoff = kNoTensionCutoff;  ///< T, Pa, the largest principal stress; ∞: none (the apex)
  Integrator integrator = kDefaultIntegrator;
  double substep_tolerance = kDefaultSubstepTolerance;  ///< `substep`: relative stress-error tolerance

  static MohrCoulombParams read(const TableReader& table);
  /// Every key with its range and default, read, checked, described or listed by `io`
  /// (FieldReader, FieldChecker, FieldDescriber, KeyLister), in the order results list them.
  template <class Io>
  void fields(const Io& io);
};

/// Principal stresses σ1 ≥ σ2 ≥ σ3 and their directions (columns of `directions`, in that order).
struct Principal {
  Vec3 values;
  Mat3 directions;
  /// Σ v_i e_i ⊗ e_i; exactly v I for equal v_i (the apex: s = 0 without round-off).
  Mat3 compose(const Vec3& v) const {
    if (v(0) == v(1) && v(1) == v(2)) return v(0) * Mat3::Identity();
    return directions * v.asDiagonal() * directions.transpose();
  }
};
/// The spectral decomposition of a symmetric tensor, eigenvalues in descending order.
Principal principal(const Mat3& sigma);

/// One plane of the elastic domain's boundary at a stress: its normalized value (f_k over the scale
/// of normalized_yield), ∂f_k/∂σ and the flow direction ∂g_k/∂σ, in the principal directions of
/// that stress.
struct YieldPlane {
  double value;
  Mat3 gradient;
  Mat3 flow;
};

class MohrCoulomb : public PerfectPlasticity, public DilatancyCutoff<MohrCoulomb> {
 public:
  using Params = MohrCoulombParams;
  static constexpr std::string_view kName = "mohr-coulomb";

  explicit MohrCoulomb(const Params& params);

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }
  Integrator integrator() const { return params_.integrator; }
  double substep_tolerance() const { return params_.substep_tolerance; }
  double sin_phi() const { return sin_phi_; }
  double sin_psi() const { return sin_psi_; }
  /// 2c cosφ, the yield function's constant.
  double cohesion_term() const { return cohesion_term_; }
  /// The apex's principal stress c cotφ (tension-positive), where the pyramid closes.
  double apex_stress() const { return cohesion_term_ / (2.0 * sin_phi_); }
  double tension_cutoff() const { return params_.tension_cutoff; }
  bool has_tension_cutoff() const { return params_.tension_cutoff < apex_stress(); }

  /// max(f, f_t) in Pa: the Mohr–Coulomb function and, if any, the cut-off; pc unused.
  double yield(const Mat3& sigma, double /*pc*/ = 0.0) const;
  double normalized_yield(const Mat3& sigma, double pc = 0.0) const;
  /// ∂f/∂σ of the active function: for Mohr–Coulomb Σ a_i e_i⊗e_i with a = (1+sinφ, 0, −(1−sinφ));
  /// at an edge (two equal principal stresses) the coefficients of the equal ones are averaged,
  /// the mean of the two planes' gradients: a subgradient that does not depend on which
  /// eigenvectors the decomposition picks in the repeated eigenspace (docs/method/derivations.md).
  Mat3 yield_gradient(const Mat3& sigma, double /*pc*/ = 0.0) const;
  /// ∂g/∂σ, as yield_gradient with ψ for φ (the cut-off's flow is associated).
  Mat3 flow_direction(const Mat3& sigma, double /*pc*/ = 0.0) const;
  /// The planes of the sorted sextant σ1 ≥ σ2 ≥ σ3 one by one, for the CVODE reference's rate
  /// equations, which combine the flows of the planes a stress lies on by Koiter's rule (an edge,
  /// a corner, the apex): f13 (the main plane), f23 and f12 (the planes that meet it along the
  /// compression edge σ1 = σ2 and the extension edge σ2 = σ3), and with a cut-off σ_k − T for
  /// k = 1, 2, 3. Off an edge only f13 (or σ1 − T) can be 0. The first plane_count() are valid.
  static constexpr int kMaxPlanes = 6;
  int plane_count() const { return has_tension_cutoff() ? 6 : 3; }
  std::array<YieldPlane, kMaxPlanes> planes(const Mat3& sigma) const;
  /// The correction after an explicit step: the implicit return of σ taken as an elastic trial.
  Mat3 correct(const Mat3& sigma, double pc = 0.0) const;
  /// True when the return of the trial is the apex or meets the tension cut-off, where substep's
  /// explicit stages cannot follow the corner: substep then takes correct(trial).
  bool beyond_tension_cutoff(const Mat3& trial) const;

  // Perfect plasticity: hardening_modulus, harden, hardening_rate, initial_preconsolidation and
  // marks (the apex) from PerfectPlasticity.
  /// The derived constants, one "  name = value" line each (`soilsph material`).
  std::string describe_constants() const;
  /// Triaxial compression, σ1 = p′ + 2q/3 and σ3 = p′ − q/3 (compression-positive) in
  /// σ1 − σ3 = 2c cosφ + (σ1 + σ3) sinφ: q = (6 sinφ p′ + 6c cosφ)/(3 − sinφ).
  FailureLine triaxial_failure_line() const {
    return {6.0 * sin_phi_ / (3.0 - sin_phi_), 3.0 * cohesion_term_ / (3.0 - sin_phi_)};
  }

  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment) const;
  /// ∂σ/∂Δε of update() without spin: the analytic consistent tangent of the implicit return for
  /// `implicit` and `substep` (the same stress map for this piecewise-linear model); central
  /// differences of the update for `explicit`.
  Mat6 consistent_tangent(const State& state, const Mat3& strain_increment) const;

 private:
  /// Σ c_i e_i⊗e_i for the plane coefficients (1+sin, 0, −(1−sin)), averaged over equal eigenvalues.
  Mat3 plane_gradient(const Mat3& sigma, double sin_angle) const;

  Params params_;
  Elasticity elasticity_;
  double sin_phi_;
  double sin_psi_;
  double cohesion_term_;
};

}  // namespace soilsph
