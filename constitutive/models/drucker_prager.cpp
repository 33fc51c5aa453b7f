#include "constitutive/models/drucker_prager.h"

#include <numbers>
#include <sstream>

#include "constitutive/derived_constants.h"
#include "constitutive/integrators/integrate.h"
#include "constitutive/material_limits.h"
#include "constitutive/tangent.h"

namespace soilsph {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
/// √J2 below which the deviator is treated as zero (the cone's apex, where ∂√J2/∂σ is undefined).
constexpr double kApexSqrtJ2 = 1e-12;
}  // namespace

template <class Io>
void DruckerPragerParams::fields(const Io& io) {
  frictional_fields(io, *this);
  io.choice_or("plastic_potential", plastic_potential, kPlasticPotentialTable);
  io.choice_or("integrator", integrator, kIntegratorTable);
  io.number_or("substep_tolerance", substep_tolerance, kSubstepToleranceRange);
}
template void DruckerPragerParams::fields(const FieldDescriber&);
template void DruckerPragerParams::fields(const KeyLister&);

DruckerPragerParams DruckerPragerParams::read(const TableReader& t) {
  return read_fields<DruckerPragerParams>(t);
}

DruckerPrager::DruckerPrager(const Params& params)
    : params_(validated(params, kName)),
      elasticity_(Elasticity::constant(params.young_modulus, params.poisson_ratio)) {
  const double tan_phi = std::tan(params.friction_angle * kDegree);
  const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);  // eq 19
  alpha_phi_ = tan_phi / root;
  k_c_ = 3.0 * params.cohesion / root;
  // The potential's slope, chosen once here so that the update reads one number (docs/method/derivations.md).
  const double psi = params.dilatancy_angle * kDegree;
  if (params.plastic_potential == PlasticPotential::PaperEq20) {
    alpha_psi_ = 3.0 * std::sin(psi);  // eq 20 as printed
  } else {
    const double tan_psi = std::tan(psi);
    alpha_psi_ = tan_psi / std::sqrt(9.0 + 12.0 * tan_psi * tan_psi);  // eq 19 with ψ for φ
  }
  require_constant_moduli(kName, params.young_modulus, elasticity_);
  require_derived(kName, "friction_angle", params.friction_angle,
                  "alpha_phi = tan(phi)/sqrt(9 + 12 tan^2(phi)) (eq 19)", alpha_phi_, "");
  require_derived(kName, "cohesion", params.cohesion, "k_c = 3c/sqrt(9 + 12 tan^2(phi)) (eq 19)", k_c_, "Pa",
                  true);
  // The apex I1 = k_c/α_φ, where tension is cut off (eq 30–31); 3c/tan φ, so a small φ overflows it.
  require_derived(kName, "cohesion", params.cohesion, "the apex's I1 = 3c/tan(phi)", apex_first_invariant(),
                  "Pa", true);
  build_cutoff(params_);
}

std::string DruckerPrager::describe_constants() const {
  const Moduli D = elasticity_.at(0.0);
  std::ostringstream out;
  out << "  K = " << D.K << " Pa, G = " << D.G << " Pa\n"
      << "  alpha_phi = " << alpha_phi_ << ", k_c = " << k_c_ << " Pa (eq 19, plane strain)\n"
      << "  alpha_psi = " << alpha_psi_ << " (the plastic potential's I1 coefficient, "
      << plastic_potential_name(params_.plastic_potential) << ")\n";
  if (limits_dilation())
    out << "  dilatancy cut-off: psi = 0 from a plastic volumetric strain of " << dilatancy_cutoff() << "\n";
  return out.str();
}

double DruckerPrager::yield(const Mat3& sigma, double) const {
  return std::sqrt(second_deviatoric_invariant(sigma)) + alpha_phi_ * sigma.trace() - k_c_;
}

double DruckerPrager::normalized_yield(const Mat3& sigma, double) const {
  const double scale =
      std::sqrt(second_deviatoric_invariant(sigma)) + alpha_phi_ * std::abs(sigma.trace()) + k_c_;
  return yield(sigma) / std::max(scale, 1e-300);
}

namespace {
/// ∂√J2/∂σ = s / (2√J2), zero at the apex. s keeps no trace: where √J2 is tiny against |p| (a cone
/// of φ → 0 at 100 kPa is 1e-6 Pa wide) σ − p I carries a round-off trace ~ε|p|, which the division
/// would turn into a volumetric flow of relative size ε|p|/√J2 (an undrained D-P path at φ = 1e-9°
/// lost 1.5e-6 of p' in `explicit`, found by the input fuzzer).
Mat3 sqrt_j2_gradient(const Mat3& sigma) {
  Mat3 s = deviator(sigma);
  s.diagonal().array() -= s.trace() / 3.0;
  const double sqrt_j2 = std::sqrt(0.5 * ddot(s, s));
  return sqrt_j2 > kApexSqrtJ2 ? Mat3(s / (2.0 * sqrt_j2)) : Mat3(Mat3::Zero());
}
}  // namespace

Mat3 DruckerPrager::yield_gradient(const Mat3& sigma, double) const {
  return sqrt_j2_gradient(sigma) + alpha_phi_ * Mat3::Identity();
}

Mat3 DruckerPrager::flow_direction(const Mat3& sigma, double) const {
  return sqrt_j2_gradient(sigma) + alpha_psi_ * Mat3::Identity();
}

Mat3 DruckerPrager::correct(const Mat3& sigma, double) const {
  // Eq 30–31: beyond the apex, shift the normal stresses so that I1 equals its apex value. There
  // −α_φ I1 + k_c = 0, so the scaling of eq 32–33 then gives r = 0: the state is the apex itself,
  // which is returned exactly (a computed shift would leave round-off of either sign).
  const double I1 = sigma.trace();
  if (-alpha_phi_ * I1 + k_c_ <= 0.0) return apex_first_invariant() / 3.0 * Mat3::Identity();
  // Eq 32–33: scale the deviator by r = (−α_φ I1 + k_c)/√J2 when r < 1, keeping I1.
  const double room = -alpha_phi_ * I1 + k_c_;
  const double sqrt_j2 = std::sqrt(second_deviatoric_invariant(sigma));
  if (room >= sqrt_j2) return sigma;
  return room / sqrt_j2 * deviator(sigma) + I1 / 3.0 * Mat3::Identity();
}

State DruckerPrager::update(const State& state, const Mat3& strain_increment,
                            const Mat3& spin_increment) const {
  return integrate(*this, state, strain_increment, spin_increment);
}

Mat6 DruckerPrager::consistent_tangent(const State& state, const Mat3& strain_increment) const {
  // `substep` converges to the exact rate solution, whose tangent the implicit one approximates to
  // first order in the increment: one update for a Newton tangent instead of the 12 of differences.
  return return_tangent_or_differences(*this, state, strain_increment);
}

}  // namespace soilsph
