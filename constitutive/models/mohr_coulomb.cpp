#include "constitutive/models/mohr_coulomb.h"

#include <Eigen/Eigenvalues>
#include <numbers>
#include <sstream>

#include "constitutive/derived_constants.h"
#include "constitutive/integrators/integrate.h"
#include "constitutive/material_limits.h"
#include "constitutive/tangent.h"

namespace soilsph {

namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
/// Principal stresses closer than this (relative to the largest) count as equal: an edge.
constexpr double kEqualPrincipal = 1e-12;
}  // namespace

template <class Io>
void MohrCoulombParams::fields(const Io& io) {
  frictional_fields(io, *this);
  io.choice_or("integrator", integrator, kIntegratorTable);
  io.number_or("substep_tolerance", substep_tolerance, kSubstepToleranceRange);
  io.number_if_given("tension_cutoff", tension_cutoff, Range::closed(0.0, limits::kMaxStress), "Pa");
}
template void MohrCoulombParams::fields(const FieldDescriber&);
template void MohrCoulombParams::fields(const KeyLister&);

MohrCoulombParams MohrCoulombParams::read(const TableReader& t) {
  return read_fields<MohrCoulombParams>(t);
}

Principal principal(const Mat3& sigma) {
  const Eigen::SelfAdjointEigenSolver<Mat3> solver(sigma);
  // Eigen sorts ascending; σ1 ≥ σ2 ≥ σ3 is the reverse.
  Principal p;
  p.values = solver.eigenvalues().reverse();
  p.directions = solver.eigenvectors().rowwise().reverse();
  return p;
}

MohrCoulomb::MohrCoulomb(const Params& params)
    : params_(validated(params, kName)),
      elasticity_(Elasticity::constant(params.young_modulus, params.poisson_ratio)),
      sin_phi_(std::sin(params.friction_angle * kDegree)),
      sin_psi_(std::sin(params.dilatancy_angle * kDegree)),
      cohesion_term_(2.0 * params.cohesion * std::cos(params.friction_angle * kDegree)) {
  require_constant_moduli(kName, params.young_modulus, elasticity_);
  require_derived(kName, "friction_angle", params.friction_angle, "sin(phi)", sin_phi_, "");
  // The apex c cot(phi), where the pyramid closes; a small φ overflows it.
  require_derived(kName, "cohesion", params.cohesion, "the apex's principal stress c cot(phi)", apex_stress(),
                  "Pa", true);
  build_cutoff(params_);
}

std::string MohrCoulomb::describe_constants() const {
  const Moduli D = elasticity_.at(0.0);
  std::ostringstream out;
  out << "  K = " << D.K << " Pa, G = " << D.G << " Pa\n"
      << "  sin(phi) = " << sin_phi_ << ", sin(psi) = " << sin_psi_ << ", 2c cos(phi) = " << cohesion_term_
      << " Pa\n"
      << "  apex = c cot(phi) = " << apex_stress() << " Pa (tension-positive)";
  if (has_tension_cutoff()) out << ", tension cut-off " << tension_cutoff() << " Pa";
  if (limits_dilation())
    out << "\n  dilatancy cut-off: psi = 0 from a plastic volumetric strain of " << dilatancy_cutoff();
  out << "\n  triaxial peak q: compression 2(c cos(phi) + s_r sin(phi))/(1 - sin(phi)), extension /(1 + "
         "sin(phi))\n";
  return out.str();
}

namespace {
double mohr_coulomb_function(const Vec3& s, double sin_phi, double cohesion_term) {
  return (s(0) - s(2)) + (s(0) + s(2)) * sin_phi - cohesion_term;
}
/// The stress scale of a normalized yield value: Σ|σ_i| + 2c cosφ (not below 1e-300).
double yield_scale(const Vec3& s, double cohesion_term) {
  return std::max(s.cwiseAbs().sum() + cohesion_term, 1e-300);
}
}  // namespace

double MohrCoulomb::yield(const Mat3& sigma, double) const {
  const Vec3 s = principal(sigma).values;
  const double f = mohr_coulomb_function(s, sin_phi_, cohesion_term_);
  return has_tension_cutoff() ? std::max(f, s(0) - tension_cutoff()) : f;
}

double MohrCoulomb::normalized_yield(const Mat3& sigma, double) const {
  const Vec3 s = principal(sigma).values;
  double f = mohr_coulomb_function(s, sin_phi_, cohesion_term_);
  if (has_tension_cutoff()) f = std::max(f, s(0) - tension_cutoff());
  return f / yield_scale(s, cohesion_term_);
}

Mat3 MohrCoulomb::plane_gradient(const Mat3& sigma, double sin_angle) const {
  const Principal p = principal(sigma);
  const Vec3& s = p.values;
  if (has_tension_cutoff() &&
      s(0) - tension_cutoff() > mohr_coulomb_function(s, sin_phi_, cohesion_term_))  // the cut-off is active
    return p.compose(Vec3(1.0, 0.0, 0.0));
  Vec3 a(1.0 + sin_angle, 0.0, -(1.0 - sin_angle));
  const double tolerance = kEqualPrincipal * std::max(s.cwiseAbs().maxCoeff(), 1e-300);
  const bool right = s(0) - s(1) <= tolerance, left = s(1) - s(2) <= tolerance;
  if (right && left)
    a.setConstant(a.sum() / 3.0);
  else if (right)
    a(0) = a(1) = 0.5 * (a(0) + a(1));
  else if (left)
    a(1) = a(2) = 0.5 * (a(1) + a(2));
  return p.compose(a);
}

Mat3 MohrCoulomb::yield_gradient(const Mat3& sigma, double) const {
  return plane_gradient(sigma, sin_phi_);
}

Mat3 MohrCoulomb::flow_direction(const Mat3& sigma, double) const {
  return plane_gradient(sigma, sin_psi_);
}

std::array<YieldPlane, MohrCoulomb::kMaxPlanes> MohrCoulomb::planes(const Mat3& sigma) const {
  const Principal p = principal(sigma);
  const Vec3& s = p.values;
  const double scale = yield_scale(s, cohesion_term_);
  // The plane of principal stresses (major, minor) = (i, j): (σ_i − σ_j) + (σ_i + σ_j) sin − 2c cosφ.
  const auto pyramid = [&](int i, int j) {
    const auto coefficients = [&](double sin_angle) {
      Vec3 a = Vec3::Zero();
      a(i) = 1.0 + sin_angle, a(j) = -(1.0 - sin_angle);
      return p.compose(a);
    };
    return YieldPlane{mohr_coulomb_function(Vec3(s(i), 0.0, s(j)), sin_phi_, cohesion_term_) / scale,
                      coefficients(sin_phi_), coefficients(sin_psi_)};
  };
  const auto cutoff = [&](int k) {
    const Mat3 n = p.compose(Vec3::Unit(k));
    return YieldPlane{(s(k) - tension_cutoff()) / scale, n, n};
  };
  std::array<YieldPlane, kMaxPlanes> planes{pyramid(0, 2), pyramid(1, 2), pyramid(0, 1)};
  if (has_tension_cutoff())
    for (int k = 0; k < 3; ++k) planes[3 + k] = cutoff(k);
  return planes;
}

Mat3 MohrCoulomb::correct(const Mat3& sigma, double) const {
  const Principal p = principal(sigma);
  const MohrCoulombReturn r = return_principal(*this, p.values, elasticity_.at(0.0));
  return r.kind == MohrCoulombReturn::Kind::Elastic ? sigma : p.compose(r.stress);
}

bool MohrCoulomb::beyond_tension_cutoff(const Mat3& trial) const {
  const MohrCoulombReturn::Kind kind =
      return_principal(*this, principal(trial).values, elasticity_.at(0.0)).kind;
  return kind == MohrCoulombReturn::Kind::Apex || kind == MohrCoulombReturn::Kind::Cutoff;
}

State MohrCoulomb::update(const State& state, const Mat3& strain_increment,
                          const Mat3& spin_increment) const {
  return integrate(*this, state, strain_increment, spin_increment);
}

Mat6 MohrCoulomb::consistent_tangent(const State& state, const Mat3& strain_increment) const {
  // With constant elasticity and flat planes `substep` reaches the exact rate solution, which the
  // principal-stress return also is while the flowing planes stay the same: its tangent serves as
  // substep's, one update for the 12 of differences (and differences of substep's error-controlled
  // stages are noisy at an edge); the driver's Newton needs a direction, not the exact derivative.
  return return_tangent_or_differences(*this, state, strain_increment);
}

}  // namespace soilsph
