#pragma once
// Checks on the pair rows a solver step filled (sph/neighbours/neighbour_list.h): that they hold a
// given kernel's W and dW/dr / r at the positions the step started from.
#include <algorithm>
#include <cmath>

#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"

namespace soilsph::test {

/// The largest relative difference, over every stored pair of every row, between the row's W and
/// dW/dr / r and `kernel`'s at |x_i − x_j| of `at` (the particles as the rows were filled).
template <int dim, class Kernel>
double largest_row_difference(const sph::PairList<dim>& rows, const sph::ParticlesOf<dim>& at,
                              const Kernel& kernel) {
  double largest = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows.for_each_pair(i, [&](const sph::PairRow::Pair& pair) {
      const sph::Vec<dim> d = at.position(i) - at.position(pair.j);
      const auto expected = kernel.value_and_gradient_factor(std::sqrt(dot(d, d)));
      largest = std::max({largest, std::abs(pair.w / expected.value - 1.0),
                          std::abs(pair.dw_over_r / expected.dw_over_r - 1.0)});
    });
  return largest;
}

}  // namespace soilsph::test
