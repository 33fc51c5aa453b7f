#include "sph/neighbours/neighbour_list.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace soilsph::sph {

void NeighbourList::build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
                          std::size_t first_boundary) {
  bool needed = false;
#pragma omp single copyprivate(needed)
  needed = search_needed(x, y);
  if (needed) search(x, y, kernel, first_boundary);
  const auto n = static_cast<std::ptrdiff_t>(x.size());
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < n; ++s) fill_row(static_cast<std::size_t>(s), x, y, kernel);
}

bool NeighbourList::search_needed(std::span<const double> x, std::span<const double> y) const {
  if (x_ref_.size() != x.size()) return true;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = x[i] - x_ref_[i], dy = y[i] - y_ref_[i];
    if (!(dx * dx + dy * dy <= half_skin2_)) return true;  // also for a non-finite position
  }
  return false;
}

void NeighbourList::search(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
                           std::size_t first_boundary) {
  const std::size_t n = x.size();
  const double radius = kernel.support() + kSkinRatio * kernel.smoothing_length();
  std::exception_ptr failure;
#pragma omp single copyprivate(failure)
  {
    try {
      cells_.build(x, y, radius);
    } catch (...) {
      failure = std::current_exception();
    }
    candidate_count_.resize(n);
    count_.assign(n, 0);
    if (candidates_.size() < n * slots_) candidates_.resize(n * slots_);
    most_candidates_ = 0;
  }
  if (failure) std::rethrow_exception(failure);  // every thread: the caller's try block catches it
  const auto rows = static_cast<std::ptrdiff_t>(n);
  for (;;) {
#pragma omp for schedule(static)
    for (std::ptrdiff_t s = 0; s < rows; ++s) {
      const std::size_t found =
          search_row(static_cast<std::size_t>(s), x, y, radius * radius, first_boundary);
      if (found > slots_) {  // rare: a compressed cluster; grow with a margin and redo
        std::size_t most = most_candidates_.load(std::memory_order_relaxed);
        while (found > most &&
               !most_candidates_.compare_exchange_weak(most, found, std::memory_order_relaxed)) {
        }
      }
    }
    const std::size_t most = most_candidates_.load(std::memory_order_relaxed);  // after the loop's barrier
#pragma omp barrier
    if (most == 0) break;
#pragma omp single
    {
      slots_ = most + most / 4;
      candidates_.resize(n * slots_);
      most_candidates_ = 0;
    }
  }
#pragma omp single
  {
    if (neighbour.size() < n * slots_) {
      for (auto* a : {&rx, &ry, &w, &gx, &gy}) a->resize(n * slots_);
      neighbour.resize(n * slots_);
    }
    const double skin = kSkinRatio * kernel.smoothing_length();
    half_skin2_ = 0.25 * skin * skin;  // (s/2)²
    x_ref_.assign(x.begin(), x.end());
    y_ref_.assign(y.begin(), y.end());
    ++searches_;
  }
}

std::size_t NeighbourList::search_row(std::size_t i, std::span<const double> x, std::span<const double> y,
                                      double radius2, std::size_t first_boundary) {
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
        if (rxij * rxij + ryij * ryij >= radius2) continue;
        if (k < last) candidates_[k] = j;
        ++k;
      }
  candidate_count_[i] = std::min(k - first, slots_);
  if (k <= last) {
    // Nearest first (ties by index, so the order is a function of the positions alone): while
    // the candidates move less than the skin, the pairs within the support stay a prefix of the
    // row and the kernel's inner branch the first of them, so the tests of fill_row are predictable.
    const double xi = x[i], yi = y[i];
    std::sort(candidates_.begin() + static_cast<std::ptrdiff_t>(first),
              candidates_.begin() + static_cast<std::ptrdiff_t>(k), [&](int a, int b) {
                const double ax = xi - x[static_cast<std::size_t>(a)], ay = yi - y[static_cast<std::size_t>(a)];
                const double bx = xi - x[static_cast<std::size_t>(b)], by = yi - y[static_cast<std::size_t>(b)];
                const double ra = ax * ax + ay * ay, rb = bx * bx + by * by;
                return ra < rb || (ra == rb && a < b);
              });
  }
  return k - first;
}

void NeighbourList::fill_row(std::size_t i, std::span<const double> x, std::span<const double> y,
                             const CubicSpline& kernel) {
  const double support2 = kernel.support() * kernel.support();
  const std::size_t first = i * slots_;
  std::size_t k = first;
  const int* candidate = candidates_.data() + first;
  for (std::size_t c = 0; c < candidate_count_[i]; ++c) {
    const int j = candidate[c];
    const auto uj = static_cast<std::size_t>(j);
    const double rxij = x[i] - x[uj], ryij = y[i] - y[uj];
    const double r2 = rxij * rxij + ryij * ryij;
    if (r2 >= support2) continue;
    const double r = std::sqrt(r2);
    const auto [value, derivative] = kernel.value_and_derivative(r);
    const double dw_over_r = r > 0.0 ? derivative / r : 0.0;
    neighbour[k] = j;
    rx[k] = rxij;
    ry[k] = ryij;
    w[k] = value;
    gx[k] = dw_over_r * rxij;
    gy[k] = dw_over_r * ryij;
    ++k;
  }
  count_[i] = k - first;
}

std::size_t NeighbourList::bytes_per_particle() const {
  return slots_ * (2 * sizeof(int) + 5 * sizeof(double)) + 2 * sizeof(std::size_t) + 2 * sizeof(double);
}

}  // namespace soilsph::sph
