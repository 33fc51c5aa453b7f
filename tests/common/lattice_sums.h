#pragma once
// Sums of a kernel over a cubic (square) lattice of particles: the discrete counterparts of its
// integral, gradient and gradient moment, for the kernel tests and for the equilibrium gradient a
// lattice of SPH particles holds under gravity (tests/sph3d/test_gravity_loading_3d.cpp).
#include <cmath>

namespace soilsph::test {

/// On a cubic (square) lattice of spacing dx, ±4 dx around a particle at the origin (so h ≤ 2 dx): Σ V W, Σ V ∇W and the
/// moment Σ V (x_i − x_j) ⊗ ∇_i W_ij, V = dx^dim, which tends to −I as the lattice refines
/// (∫ u ⊗ ∇W(u) du = −I ∫ W du by parts, u = x_i − x_j, for a kernel of unit integral).
struct LatticeSums {
  double sum = 0.0;
  double gradient[3] = {0, 0, 0};
  double moment[3][3] = {};
};
template <class Kernel>
LatticeSums lattice_sums(const Kernel& W, double dx) {
  constexpr int dim = Kernel::dimension;
  LatticeSums s;
  const double volume = std::pow(dx, dim);
  const int zmax = dim == 3 ? 4 : 0;
  for (int a = -4; a <= 4; ++a)
    for (int b = -4; b <= 4; ++b)
      for (int c = -zmax; c <= zmax; ++c) {
        const double r[3] = {-a * dx, -b * dx, -c * dx};  // x_i − x_j
        const double rn = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        s.sum += volume * W.value(rn);
        const double g = W.value_and_gradient_factor(rn).dw_over_r;
        for (int p = 0; p < 3; ++p) {
          s.gradient[p] += volume * g * r[p];
          for (int q = 0; q < 3; ++q) s.moment[p][q] += volume * r[p] * g * r[q];
        }
      }
  return s;
}

}  // namespace soilsph::test
