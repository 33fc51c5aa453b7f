#include "sph/neighbours/neighbour_list.h"

#include <cmath>

namespace soilsph::sph {

namespace {
/// Calls f(j, dx, dy, r²) for every j ≠ i within `support` of point i.
template <class F>
void for_each_near(const CellList& cells, std::span<const double> x, std::span<const double> y, std::size_t i,
                   double support, F&& f) {
  const double support2 = support * support;
  const int cx = cells.cell_x(x[i]), cy = cells.cell_y(y[i]);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      for (const int j : cells.particles_in(cx + dx, cy + dy)) {
        if (static_cast<std::size_t>(j) == i) continue;
        const double rx = x[i] - x[j], ry = y[i] - y[j];
        const double r2 = rx * rx + ry * ry;
        if (r2 < support2) f(j, rx, ry, r2);
      }
}
}  // namespace

void NeighbourList::build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel) {
  const double support = kernel.support();
  cells_.build(x, y, support);
  const std::size_t n = x.size();
  const auto ni = static_cast<std::ptrdiff_t>(n);
  offsets_.resize(n + 1);
  offsets_[0] = 0;

  // Pass 1: count, pass 2: fill at the prefix-summed offsets. Buffers only grow.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < ni; ++s) {
    const auto i = static_cast<std::size_t>(s);
    std::size_t count = 0;
    for_each_near(cells_, x, y, i, support, [&](int, double, double, double) { ++count; });
    offsets_[i + 1] = count;
  }
  for (std::size_t i = 0; i < n; ++i) offsets_[i + 1] += offsets_[i];
  const std::size_t pairs = offsets_[n];
  if (neighbour.size() < pairs) {
    for (auto* a : {&rx, &ry, &w, &gx, &gy}) a->resize(pairs);
    neighbour.resize(pairs);
  }

#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t s = 0; s < ni; ++s) {
    const auto i = static_cast<std::size_t>(s);
    std::size_t k = offsets_[i];
    for_each_near(cells_, x, y, i, support, [&](int j, double dx, double dy, double r2) {
      const double r = std::sqrt(r2);
      const double dw_over_r = r > 0.0 ? kernel.derivative(r) / r : 0.0;
      neighbour[k] = j;
      rx[k] = dx;
      ry[k] = dy;
      w[k] = kernel.value(r);
      gx[k] = dw_over_r * dx;
      gy[k] = dw_over_r * dy;
      ++k;
    });
  }
}

}  // namespace soilsph::sph
