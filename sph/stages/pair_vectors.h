#pragma once
/// @file
/// What a stage reads of one pair (i, j) whatever the dimension: j, W_ij, x_i − x_j and ∇_i W_ij as
/// arrays of the dimension. The pair rows store W and dW/dr / r only (neighbours/neighbour_list.h);
/// x_i − x_j is taken from the positions here, ∇_i W_ij = dW/dr / r · (x_i − x_j). Stages written
/// once over PairVectors<dim> read as their equation in index notation.
#include <array>
#include <cstddef>

#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::sph {

template <int dim>
struct PairVectors {
  std::size_t j;
  double w;                   ///< W_ij
  std::array<double, dim> r;  ///< x_i − x_j (m)
  std::array<double, dim> g;  ///< ∇_i W_ij (1/m^{dim+1})
};

/// Calls f(PairVectors) for every pair of particle i of the list `nl` over the particles p. Always
/// inlined: GCC 12 otherwise keeps it out of line in the velocity-gradient pass, with f called per
/// pair, which made the plane's step 12 % slower at the paper's column (perf, 2026-12-05).
template <int dim, class F>
[[gnu::always_inline]] inline void for_each_pair_vectors(const ParticlesOf<dim>& p, const PairList<dim>& nl,
                                                         std::size_t i, F&& f) {
  const auto x = p.coordinates();
  std::array<double, dim> xi;
  for (int d = 0; d < dim; ++d) xi[d] = x[d][i];
  nl.for_each_pair(i, [&](const PairRow::Pair& q) {
    PairVectors<dim> v{.j = q.j, .w = q.w, .r = {}, .g = {}};
    for (int d = 0; d < dim; ++d) v.r[d] = xi[d] - x[d][q.j], v.g[d] = q.dw_over_r * v.r[d];
    f(v);
  });
}

/// a · b, summed from the first component on (the order the plane's formulas were written in).
template <std::size_t n>
inline double dot(const std::array<double, n>& a, const std::array<double, n>& b) {
  double s = a[0] * b[0];
  for (std::size_t k = 1; k < n; ++k) s += a[k] * b[k];
  return s;
}

/// The stress arrays of the momentum equation, in symmetric_index order.
template <int dim>
std::array<std::vector<double>*, kSymmetricComponents<dim>> stress_arrays(ParticlesOf<dim>& p) {
  if constexpr (dim == 2)
    return {&p.sxx, &p.syy, &p.sxy};
  else
    return {&p.sxx, &p.syy, &p.szz, &p.sxy, &p.sxz, &p.syz};
}
template <int dim>
std::array<const std::vector<double>*, kSymmetricComponents<dim>> stress_arrays(const ParticlesOf<dim>& p) {
  if constexpr (dim == 2)
    return {&p.sxx, &p.syy, &p.sxy};
  else
    return {&p.sxx, &p.syy, &p.szz, &p.sxy, &p.sxz, &p.syz};
}

}  // namespace soilsph::sph
