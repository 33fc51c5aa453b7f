#pragma once
/// @file
/// The linear algebra of mixed control shared by the Newton driver and the CVODE reference:
/// which components are free, the 6×6 Voigt elastic stiffness, and the solve of the free strain
/// components from a 6×6 (algorithmic or continuum) tangent.
#include <Eigen/LU>

#include "constitutive/elasticity.h"
#include "constitutive/voigt.h"
#include "verification/paths/load_path.h"

namespace soilsph::verification {

/// Indices of a leg's stress-imposed (free strain) and strain-imposed components.
struct Partition {
  int free[6];
  int n_free = 0;
  int fixed[6];
  int n_fixed = 0;
  explicit Partition(const Leg& leg) {
    for (int k = 0; k < 6; ++k) (leg.stress_imposed[k] ? free[n_free++] : fixed[n_fixed++]) = k;
  }
};

/// The 6×6 Voigt stiffness (engineering shear strains → stresses) of moduli D.
inline Mat6 voigt_stiffness(const Moduli& D) {
  Mat6 C;
  for (int k = 0; k < 6; ++k) C.col(k) = stress_to_voigt(D.stiffness(strain_from_voigt(Vec6::Unit(k))));
  return C;
}

/// Sets the free entries of `x` to the solution of C_ff x_f = b_f − C_fi x_i (x_i as given in x).
inline void solve_free(const Mat6& C, const Partition& part, const Vec6& b, Vec6& x) {
  if (part.n_free == 0) return;
  Eigen::MatrixXd A(part.n_free, part.n_free);
  Eigen::VectorXd rhs(part.n_free);
  for (int a = 0; a < part.n_free; ++a) {
    rhs(a) = b(part.free[a]);
    for (int c = 0; c < part.n_fixed; ++c) rhs(a) -= C(part.free[a], part.fixed[c]) * x(part.fixed[c]);
    for (int c = 0; c < part.n_free; ++c) A(a, c) = C(part.free[a], part.free[c]);
  }
  const Eigen::VectorXd solution = A.partialPivLu().solve(rhs);
  for (int a = 0; a < part.n_free; ++a) x(part.free[a]) = solution(a);
}

}  // namespace soilsph::verification
