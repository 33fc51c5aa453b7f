#include "sph/neighbours/neighbour_list.h"

#include <algorithm>
#include <cmath>

namespace soilsph::sph {

void NeighbourList::build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
                          std::size_t first_boundary) {
  const std::size_t n = x.size();
  const double skin = kSkinRatio * kernel.smoothing_length();
  if (x_ref_.size() != n || moved_beyond_skin(x, y, skin)) {
    const double radius = kernel.support() + skin;
    cells_.build(x, y, radius);
    candidate_count_.resize(n);
    for (;;) {
      if (candidates_.size() < n * candidate_slots_) candidates_.resize(n * candidate_slots_);
      const std::size_t most = search(x, y, radius, first_boundary);
      if (most <= candidate_slots_) break;
      candidate_slots_ = most + most / 4;  // rare: a compressed cluster; grow with a margin and redo
    }
    x_ref_.assign(x.begin(), x.end());
    y_ref_.assign(y.begin(), y.end());
    ++searches_;
  }
  count_.resize(n);
  for (;;) {
    if (neighbour.size() < n * slots_) {
      for (auto* a : {&rx, &ry, &w, &gx, &gy}) a->resize(n * slots_);
      neighbour.resize(n * slots_);
    }
    const std::size_t most = fill(x, y, kernel);
    if (most <= slots_) return;
    slots_ = most + most / 4;
  }
}

bool NeighbourList::moved_beyond_skin(std::span<const double> x, std::span<const double> y,
                                      double skin) const {
  const double limit2 = 0.25 * skin * skin;  // (s/2)²
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  bool moved = false;
#pragma omp parallel for schedule(static) reduction(|| : moved)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const double dx = x[s] - x_ref_[s], dy = y[s] - y_ref_[s];
    moved = moved || dx * dx + dy * dy > limit2 || !std::isfinite(dx + dy);
  }
  return moved;
}

std::size_t NeighbourList::search(std::span<const double> x, std::span<const double> y, double radius,
                                  std::size_t first_boundary) {
  const double radius2 = radius * radius;
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  std::size_t most = 0;
#pragma omp parallel for schedule(static) reduction(max : most)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const bool boundary_i = i >= first_boundary;
    const int cx = cells_.cell_x(x[i]), cy = cells_.cell_y(y[i]);
    const std::size_t first = i * candidate_slots_, last = first + candidate_slots_;
    std::size_t k = first;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (const int j : cells_.particles_in(cx + dx, cy + dy)) {
          const auto uj = static_cast<std::size_t>(j);
          if (uj == i || (boundary_i && uj >= first_boundary)) continue;
          const double rxij = x[i] - x[uj], ryij = y[i] - y[uj];
          if (rxij * rxij + ryij * ryij >= radius2) continue;
          if (k < last) candidates_[k] = j;
          ++k;
        }
    candidate_count_[i] = std::min(k - first, candidate_slots_);
    most = std::max(most, k - first);
  }
  return most;
}

std::size_t NeighbourList::fill(std::span<const double> x, std::span<const double> y,
                                const CubicSpline& kernel) {
  const double support2 = kernel.support() * kernel.support();
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  std::size_t most = 0;
#pragma omp parallel for schedule(static) reduction(max : most)
  for (std::ptrdiff_t s = 0; s < n; ++s) {
    const auto i = static_cast<std::size_t>(s);
    const std::size_t first = i * slots_, last = first + slots_;
    std::size_t k = first;
    const int* candidate = candidates_.data() + i * candidate_slots_;
    for (std::size_t c = 0; c < candidate_count_[i]; ++c) {
      const int j = candidate[c];
      const auto uj = static_cast<std::size_t>(j);
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
