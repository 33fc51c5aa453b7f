#include "sph/neighbours/neighbour_list.h"

#include <algorithm>
#include <cmath>

namespace soilsph::sph {

void NeighbourList::build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
                          std::size_t first_boundary) {
  cells_.build(x, y, kernel.support());
  count_.resize(x.size());
  for (;;) {
    const std::size_t pairs = x.size() * slots_;
    if (neighbour.size() < pairs) {
      for (auto* a : {&rx, &ry, &w, &gx, &gy}) a->resize(pairs);
      neighbour.resize(pairs);
    }
    const std::size_t most = fill(x, y, kernel, first_boundary);
    if (most <= slots_) return;
    slots_ = most + most / 4;  // rare: a compressed cluster; grow with a margin and redo
  }
}

std::size_t NeighbourList::fill(std::span<const double> x, std::span<const double> y,
                                const CubicSpline& kernel, std::size_t first_boundary) {
  const double support2 = kernel.support() * kernel.support();
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  std::size_t most = 0;
#pragma omp parallel for schedule(static) reduction(max : most)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const bool boundary_i = i >= first_boundary;
    const int cx = cells_.cell_x(x[i]), cy = cells_.cell_y(y[i]);
    const std::size_t first = i * slots_, last = first + slots_;
    std::size_t k = first;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (const int j : cells_.particles_in(cx + dx, cy + dy)) {
          const auto uj = static_cast<std::size_t>(j);
          if (uj == i || (boundary_i && uj >= first_boundary)) continue;
          const double rxij = x[i] - x[uj], ryij = y[i] - y[uj];
          const double r2 = rxij * rxij + ryij * ryij;
          if (r2 >= support2) continue;
          if (k < last) {
            const double r = std::sqrt(r2);
            const double dw_over_r = r > 0.0 ? kernel.derivative(r) / r : 0.0;
            neighbour[k] = j;
            rx[k] = rxij;
            ry[k] = ryij;
            w[k] = kernel.value(r);
            gx[k] = dw_over_r * rxij;
            gy[k] = dw_over_r * ryij;
          }
          ++k;
        }
    count_[i] = std::min(k - first, slots_);
    most = std::max(most, k - first);
  }
  return most;
}

}  // namespace soilsph::sph
