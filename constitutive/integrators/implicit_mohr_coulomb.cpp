#include "constitutive/integrators/implicit_mohr_coulomb.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>  // the static lists of active sets only

namespace soilsph {

namespace {
using Kind = MohrCoulombReturn::Kind;

/// One plane f = a·σ − b with flow direction g, in sorted principal stresses.
struct Plane {
  Vec3 a, g;
  double b;
};

/// The six planes: 0 main (σ1, σ3), 1 with σ2 for σ1, 2 with σ2 for σ3, 3–5 the cut-offs σ_i = T.
std::array<Plane, 6> planes(const MohrCoulomb& m) {
  const double s = m.sin_phi(), t = m.sin_psi(), c = m.cohesion_term(), T = m.tension_cutoff();
  return {{{Vec3(1 + s, 0, -(1 - s)), Vec3(1 + t, 0, -(1 - t)), c},
           {Vec3(0, 1 + s, -(1 - s)), Vec3(0, 1 + t, -(1 - t)), c},
           {Vec3(1 + s, -(1 - s), 0), Vec3(1 + t, -(1 - t), 0), c},
           {Vec3(1, 0, 0), Vec3(1, 0, 0), T},
           {Vec3(0, 1, 0), Vec3(0, 1, 0), T},
           {Vec3(0, 0, 1), Vec3(0, 0, 1), T}}};
}

struct ActiveSet {
  Kind kind;
  std::vector<int> planes;
};

/// The sets tried in turn (the cut-off's only with a cut-off below the apex).
const std::vector<ActiveSet>& active_sets(bool cutoff) {
  static const std::vector<ActiveSet> plain = {
      {Kind::Plane, {0}}, {Kind::RightEdge, {0, 1}}, {Kind::LeftEdge, {0, 2}}};
  // The corner where the right edge meets the cut-off, σ1 = σ2 = T on the pyramid, lies on four
  // planes (0, 1, 3, 4): its cone of flow directions is the union of those of the four triples
  // (Carathéodory in three dimensions), so each triple is a set of its own. Triaxial compression
  // at low confinement ends there (σ'_r = −T, σ'_a on the failure line).
  static const std::vector<ActiveSet> with_cutoff = {
      {Kind::Plane, {0}},        {Kind::RightEdge, {0, 1}}, {Kind::LeftEdge, {0, 2}},
      {Kind::Cutoff, {3}},       {Kind::Cutoff, {0, 3}},    {Kind::Cutoff, {0, 2, 3}},
      {Kind::Cutoff, {3, 4}},    {Kind::Cutoff, {0, 3, 4}}, {Kind::Cutoff, {0, 1, 3}},
      {Kind::Cutoff, {0, 1, 4}}, {Kind::Cutoff, {1, 3, 4}}, {Kind::Cutoff, {3, 4, 5}}};
  return cutoff ? with_cutoff : plain;
}

/// At most three active planes: matrices of fixed capacity, so a return allocates nothing.
using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
using Columns = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3>;
using Multipliers = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

Mat3 principal_stiffness(const Moduli& D) {
  return (D.K - 2.0 * D.G / 3.0) * Mat3::Ones() + 2.0 * D.G * Mat3::Identity();
}
}  // namespace

MohrCoulombReturn return_principal(const MohrCoulomb& model, const Vec3& trial, const Moduli& D) {
  MohrCoulombReturn r;
  r.stress = trial;
  const auto all = planes(model);
  // The trial is sorted, so the main plane and σ1's cut-off decide whether it yields.
  if (all[0].a.dot(trial) - all[0].b <= 0.0 && all[3].a.dot(trial) - all[3].b <= 0.0) return r;
  const Mat3 Dp = principal_stiffness(D);
  const bool cutoff = model.has_tension_cutoff();
  // Tolerances relative to the stresses involved.
  const double scale = trial.cwiseAbs().sum() + model.cohesion_term() + (cutoff ? std::abs(model.tension_cutoff()) : 0.0);
  const double tolerance = 1e-10 * scale;
  for (const ActiveSet& set : active_sets(cutoff)) {
    const int n = static_cast<int>(set.planes.size());
    Columns N(3, n), DG(3, n);
    Multipliers f(n);
    for (int k = 0; k < n; ++k) {
      const Plane& pk = all[set.planes[k]];
      N.col(k) = pk.a;
      DG.col(k) = Dp * pk.g;
      f(k) = pk.a.dot(trial) - pk.b;
    }
    const Square A = N.transpose() * DG;
    const Eigen::FullPivLU<Square> lu(A);
    if (!lu.isInvertible()) continue;
    const Multipliers d_gamma = lu.solve(f);
    if ((d_gamma.array() < 0.0).any()) continue;
    const Vec3 sigma = trial - DG * d_gamma;
    if (sigma(0) < sigma(1) - tolerance || sigma(1) < sigma(2) - tolerance) continue;
    bool inside = true;  // (without a cut-off T = ∞ and its planes hold)
    for (const Plane& p : all) inside = inside && p.a.dot(sigma) - p.b <= tolerance;
    if (!inside) continue;
    r.kind = set.kind;
    r.stress = sigma;
    // Equal stresses of an edge or corner exactly equal, and those on a cut-off exactly T (so s = 0
    // at a corner is exact).
    const auto has = [&](int plane) { return std::ranges::find(set.planes, plane) != set.planes.end(); };
    if (has(1))
      r.stress(0) = r.stress(1) = has(3) || has(4) ? model.tension_cutoff() : 0.5 * (sigma(0) + sigma(1));
    if (has(2)) r.stress(1) = r.stress(2) = 0.5 * (sigma(1) + sigma(2));
    for (int k = 3; k < 6; ++k)
      if (has(k)) r.stress(k - 3) = model.tension_cutoff();
    r.multiplier = d_gamma.sum();
    r.jacobian = Mat3::Identity() - DG * lu.solve(Square(N.transpose()));
    r.plastic_strain = Dp.inverse() * (trial - r.stress);
    return r;
  }
  // The apex of the pyramid: every direction of flow from there is a mix of the planes' potentials,
  // and the stress does not depend on the trial.
  r.kind = Kind::Apex;
  r.stress.setConstant(cutoff ? model.tension_cutoff() : model.apex_stress());
  r.plastic_strain = Dp.inverse() * (trial - r.stress);
  r.multiplier = r.plastic_strain.norm();
  r.jacobian.setZero();
  return r;
}

namespace {
/// ∂σ/∂σ_tr (Voigt stress to Voigt stress) of σ = Σ σ_i(σ_tr) e_i⊗e_i with the eigenvectors of σ_tr.
Mat6 spectral_jacobian(const Principal& trial, const MohrCoulombReturn& r) {
  const Vec3& t = trial.values;
  const Vec3& s = r.stress;
  const Mat3& J = r.jacobian;
  const double scale = t.cwiseAbs().maxCoeff() + 1.0;
  Mat3 ratio = Mat3::Zero();  // (σ_i − σ_j)/(σ_tr,i − σ_tr,j), its limit at equal trial stresses
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      if (i == j) continue;
      const double dt = t(i) - t(j);
      ratio(i, j) = std::abs(dt) > 1e-12 * scale ? (s(i) - s(j)) / dt
                                                  : 0.5 * (J(i, i) - J(i, j) - J(j, i) + J(j, j));
    }
  const Mat3& Q = trial.directions;
  Mat6 M;
  for (int k = 0; k < 6; ++k) {
    Vec6 unit = Vec6::Zero();
    unit(k) = 1.0;
    const Mat3 d_trial = Q.transpose() * stress_from_voigt(unit) * Q;  // in the principal basis
    const Vec3 d_principal = J * d_trial.diagonal();
    Mat3 d_sigma = ratio.cwiseProduct(d_trial);
    d_sigma.diagonal() = d_principal;
    M.col(k) = stress_to_voigt(Q * d_sigma * Q.transpose());
  }
  return M;
}
}  // namespace

State implicit_update(const MohrCoulomb& model, const State& start, const Mat3& strain_increment, Mat6* tangent) {
  const Moduli D = model.elasticity().at(0.0);
  const Mat3 trial = start.stress + D.stiffness(strain_increment);
  State next = start;
  next.plastic_multiplier = 0.0;
  const Principal pr = principal(trial);
  const MohrCoulombReturn r = return_principal(model, pr.values, D);
  if (r.kind == Kind::Elastic) {
    next.stress = trial;
    if (tangent) *tangent = voigt_isotropic_stiffness(D.K, D.G);
    return next;
  }
  next.stress = pr.compose(r.stress);
  accumulate_plastic_strain(next, pr.compose(r.plastic_strain));
  next.plastic_multiplier = r.multiplier;
  if (tangent) *tangent = spectral_jacobian(pr, r) * voigt_isotropic_stiffness(D.K, D.G);
  return next;
}

}  // namespace soilsph
