#include "verification/closed_form/mohr_coulomb_triaxial.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace soilsph::verification {

MohrCoulombTriaxial::MohrCoulombTriaxial(const MohrCoulomb& model, double p_initial, bool undrained)
    : p_initial_(p_initial),
      undrained_(undrained),
      young_(model.params().young_modulus),
      poisson_(model.params().poisson_ratio),
      K_(model.elasticity().at(0.0).K),
      G_(model.elasticity().at(0.0).G),
      sin_phi_(model.sin_phi()),
      sin_psi_(model.sin_psi()),
      cohesion_(0.5 * model.cohesion_term()),
      cutoff_(model.has_tension_cutoff() ? model.tension_cutoff() : std::numeric_limits<double>::infinity()) {
}

double MohrCoulombTriaxial::yield_q(int sign) const {
  const double strength = 2.0 * (cohesion_ + p_initial_ * sin_phi_);
  // Drained, σ_r = p_i is the minor (compression) or major (extension) principal stress; undrained,
  // p' = p_i at first yield and σ_r = p' − q/3.
  return strength / (1.0 - sign * sin_phi_ / (undrained_ ? 3.0 : 1.0));
}

double MohrCoulombTriaxial::yield_strain(int sign) const {
  return sign * yield_q(sign) / (undrained_ ? 3.0 * G_ : young_);
}

double MohrCoulombTriaxial::cutoff_q(int sign) const {
  // Drained the radial stress stays at p_i, so only extension's axial stress can reach −T; undrained
  // p' = p_i while elastic, and σ'_r = p_i − q/3 (compression) or σ'_a = p_i + 2q/3 (extension) is −T.
  if (!std::isfinite(cutoff_) || (!undrained_ && sign > 0)) return std::numeric_limits<double>::infinity();
  return (p_initial_ + cutoff_) * (undrained_ ? (sign > 0 ? 3.0 : 1.5) : 1.0);
}

ReferencePoint MohrCoulombTriaxial::at(double eps_a) const {
  const int sign = eps_a < 0.0 ? -1 : 1;
  if (cutoff_q(sign) < yield_q(sign))
    return undrained_ ? undrained_on_cutoff(eps_a) : drained_on_cutoff(eps_a);
  const double eps_y = yield_strain(sign);
  const double elastic = sign * std::min(sign * eps_a, sign * eps_y);  // ε_a up to first yield
  const double beyond = std::max(sign * (eps_a - eps_y), 0.0);         // |ε_a| past first yield
  const double t = sin_psi_;
  if (!undrained_) {
    const double q = young_ * elastic;
    // dε_v/dε_a = −2σt/(1 − σt) over ε_a − ε_y = σ·beyond: dilation on either side.
    const double eps_v = (1.0 - 2.0 * poisson_) * elastic - 2.0 * t / (1.0 - sign * t) * beyond;
    return {eps_a, eps_v, p_initial_ + q / 3.0, q, 0.0};
  }
  const double p = p_initial_ + edge_rise(sign, beyond);
  const double q = 3.0 * G_ * elastic + sign * failure_slope(sign) * (p - p_initial_);
  return {eps_a, 0.0, p, q, 0.0};
}

double MohrCoulombTriaxial::failure_slope(int sign) const {
  return 6.0 * sin_phi_ / (3.0 - sign * sin_phi_);
}

double MohrCoulombTriaxial::edge_rise(int sign, double beyond) const {
  const double t = sin_psi_;
  const double d_gamma =
      3.0 * G_ * beyond / (6.0 * G_ - 2.0 * sign * G_ * t + 4.0 * K_ * failure_slope(sign) * t);
  return 4.0 * K_ * t * d_gamma;
}

ReferencePoint MohrCoulombTriaxial::drained_on_cutoff(double eps_a) const {
  // Extension: σ'_a = −T from |q| = p_i + T on, with σ'_r = p_i; the cut-off's flow is axial only, so
  // every further axial strain is plastic extension (dε_v/dε_a = 1).
  const double eps_c = -(p_initial_ + cutoff_) / young_;
  const double elastic = std::max(eps_a, eps_c);
  const double q = young_ * elastic;
  return {eps_a, (1.0 - 2.0 * poisson_) * elastic + (eps_a - elastic), p_initial_ + q / 3.0, q, 0.0};
}

ReferencePoint MohrCoulombTriaxial::undrained_on_cutoff(double eps_a) const {
  const int sign = eps_a < 0.0 ? -1 : 1;
  const double magnitude = sign * eps_a;
  const double q_cut = cutoff_q(sign);
  const double eps_cut = q_cut / (3.0 * G_);
  if (magnitude <= eps_cut) return {eps_a, 0.0, p_initial_, 3.0 * G_ * eps_a, 0.0};
  // On the cut-off the stress at −T holds and the other rises: compression, both radial stresses at
  // −T and no axial plastic strain, so σ̇'_a = E ε̇_a (uniaxial stress); extension, the axial stress at
  // −T, ε̇_r = −ε̇_a/2 elastic and σ̇'_a = 0 give σ̇'_r = 3GK/(K + 4G/3) |ε̇_a|. Until the rising one
  // reaches the pyramid, σ' = (2c cosφ − (1 + sinφ) T)/(1 − sinφ) in either direction (the corner).
  const double start = sign > 0 ? p_initial_ + 2.0 * q_cut / 3.0 : p_initial_ + q_cut / 3.0;
  const double rate = sign > 0 ? young_ : 3.0 * G_ * K_ / (K_ + 4.0 * G_ / 3.0);
  const double corner = (2.0 * cohesion_ - (1.0 + sin_phi_) * cutoff_) / (1.0 - sin_phi_);
  const double eps_corner = eps_cut + (corner - start) / rate;
  const double rising = start + rate * (std::min(magnitude, eps_corner) - eps_cut);
  const double axial = sign > 0 ? rising : -cutoff_, radial = sign > 0 ? -cutoff_ : rising;
  const double p_corner = (axial + 2.0 * radial) / 3.0;
  if (magnitude <= eps_corner) return {eps_a, 0.0, p_corner, axial - radial, 0.0};
  // From the corner along the edge: with ψ > 0 p' rises at the edge's rate and the stress leaves the
  // cut-off (σ'_r in compression and σ'_a in extension grow with p' on the failure line); ψ = 0 stays.
  const double p = p_corner + edge_rise(sign, magnitude - eps_corner);
  return {eps_a, 0.0, p, sign * 2.0 * (cohesion_ + p * sin_phi_) / (1.0 - sign * sin_phi_ / 3.0), 0.0};
}

}  // namespace soilsph::verification
