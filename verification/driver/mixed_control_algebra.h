#pragma once
/// @file
/// The linear algebra of mixed control shared by the Newton driver and the CVODE reference:
/// which components are free, the 6×6 Voigt elastic stiffness, and the solve of the free strain
/// components from a 6×6 (algorithmic or continuum) tangent.
#include <Eigen/QR>

#include "constitutive/elasticity.h"
#include "constitutive/voigt.h"
#include "verification/paths/load_path.h"

namespace soilsph::verification {

/// Indices of a leg's stress-imposed (free strain) and strain-imposed components, and whether the
/// leg is undrained (its imposed stresses are then total stresses, and ε_v is held).
struct Partition {
  int free[6];
  int n_free = 0;
  int fixed[6];
  int n_fixed = 0;
  bool undrained = false;
  explicit Partition(const Leg& leg) : undrained(leg.undrained) {
    for (int k = 0; k < 6; ++k) (leg.stress_imposed[k] ? free[n_free++] : fixed[n_fixed++]) = k;
  }
};

/// A pivot of the free system below this fraction of the largest counts as zero (solve_free).
inline constexpr double kSingularPivot = 1e-10;

/// m = δ_ij in Voigt form: the pore pressure acts on the normal components only.
inline double voigt_identity(int k) { return k < 3 ? 1.0 : 0.0; }

/// The 6×6 Voigt stiffness (engineering shear strains → stresses) of moduli D.
inline Mat6 voigt_stiffness(const Moduli& D) {
  Mat6 C;
  for (int k = 0; k < 6; ++k) C.col(k) = stress_to_voigt(D.stiffness(strain_from_voigt(Vec6::Unit(k))));
  return C;
}

/// Sets the free entries of `x` to the solution of C_ff x_f = b_f − C_fi x_i (x_i as given in x) and
/// returns 0. Undrained, b holds total stresses σ = σ' − u m (tension-positive σ', compression-positive
/// pore pressure u), so the pore pressure change is one more unknown, and the volume is held:
///   C_ff x_f − m_f du = b_f − C_fi x_i,   m_f · x_f = −m_i · x_i;
/// returns du. (Needs a stress-imposed normal component, which the programme reader checks.)
///
/// The system may be singular: at an edge of a perfectly plastic pyramid (Mohr–Coulomb in
/// triaxial compression or extension, two principal stresses equal and both planes active) the
/// stress stays on the edge whatever the split of the lateral strains, so σ_yy − σ_zz does not
/// depend on ε_yy − ε_zz and two imposed lateral stresses are one equation. The deformation is
/// then not unique, and the solution taken is the one of least norm (a complete orthogonal
/// decomposition, rank decided relative to the largest pivot): the Newton correction has no part
/// in the undetermined direction, which keeps the split of the elastic guess (ε_yy = ε_zz on a triaxial
/// path). For a regular system it is the ordinary solution. The border is scaled by the largest
/// stiffness so that the rank decision compares like with like.
inline double solve_free(const Mat6& C, const Partition& part, const Vec6& b, Vec6& x) {
  if (part.n_free == 0) return 0.0;
  const int n = part.n_free + (part.undrained ? 1 : 0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (int a = 0; a < part.n_free; ++a) {
    rhs(a) = b(part.free[a]);
    for (int c = 0; c < part.n_fixed; ++c) rhs(a) -= C(part.free[a], part.fixed[c]) * x(part.fixed[c]);
    for (int c = 0; c < part.n_free; ++c) A(a, c) = C(part.free[a], part.free[c]);
  }
  // (The whole tangent's scale: the free block alone vanishes where the imposed stresses sit on
  // the tension cut-off, and so would the volume condition with it; 1 Pa where everything does, at
  // a corner that fixes the stress.)
  const double largest = C.cwiseAbs().maxCoeff();
  const double scale = largest > 0.0 ? largest : 1.0;
  if (part.undrained) {  // unknown du/scale, equation scale·(m · x) = −scale·(m_i · x_i)
    for (int a = 0; a < part.n_free; ++a) {
      A(a, part.n_free) = -scale * voigt_identity(part.free[a]);
      A(part.n_free, a) = scale * voigt_identity(part.free[a]);
    }
    for (int c = 0; c < part.n_fixed; ++c)
      rhs(part.n_free) -= scale * voigt_identity(part.fixed[c]) * x(part.fixed[c]);
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition;
  decomposition.setThreshold(kSingularPivot);
  decomposition.compute(A);
  const Eigen::VectorXd solution = decomposition.solve(rhs);
  for (int a = 0; a < part.n_free; ++a) x(part.free[a]) = solution(a);
  return part.undrained ? scale * solution(part.n_free) : 0.0;
}

}  // namespace soilsph::verification
