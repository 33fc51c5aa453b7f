#include "sph/neighbours/neighbour_list.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <vector>

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
  const SearchRadii radii{radius * radius, kernel.support() * kernel.support(),
                          kernel.smoothing_length() * kernel.smoothing_length()};
  std::exception_ptr failure;
#pragma omp single copyprivate(failure)
  {
    try {
      cells_.build(x, y, radius, true);
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
          search_row(static_cast<std::size_t>(s), x, y, radii, first_boundary);
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
                                      const SearchRadii& radii, std::size_t first_boundary) {
  struct Candidate {
    double r2;
    int j;
  };
  thread_local std::vector<Candidate> found;  // grows to the largest row once, then reused
  found.clear();
  const bool boundary_i = i >= first_boundary;
  const auto band = [&](double r2) { return static_cast<std::size_t>(r2 >= radii.inner2) + (r2 >= radii.support2); };
  const double xi = x[i], yi = y[i];
  const int cx = cells_.cell_x(xi), cy = cells_.cell_y(yi);
  for (int dy = -1; dy <= 1; ++dy) {
    const CellList::Run run = cells_.row_of_three(cx, cy + dy);
    for (std::size_t k = 0; k < run.size; ++k) {
      const double rxij = xi - run.x[k], ryij = yi - run.y[k], r2 = rxij * rxij + ryij * ryij;
      if (r2 >= radii.search2) continue;
      const int j = run.index[k];
      const auto uj = static_cast<std::size_t>(j);
      if (uj == i || (boundary_i && uj >= first_boundary)) continue;
      found.push_back({r2, j});
    }
  }
  const std::size_t count = found.size(), first = i * slots_;
  candidate_count_[i] = std::min(count, slots_);
  if (count <= slots_) {
    // In three bands, each in the search's order: within h (the kernel's inner branch), within the
    // support 2h (its outer branch), and the skin beyond. While the candidates move less than the
    // skin, a row's pairs stay nearly a prefix of it and each band takes one branch of the kernel,
    // so the tests of fill_row are predicted. A stable counting partition, O(n): the order is a
    // function of the positions alone (the cell order, then the index), as a sort's would be.
    std::size_t next[3] = {0, 0, 0};
    for (const Candidate& c : found) ++next[band(c.r2)];
    next[2] = next[0] + next[1], next[1] = next[0], next[0] = 0;
    for (const Candidate& c : found) candidates_[first + next[band(c.r2)]++] = c.j;
  }
  return count;
}

void NeighbourList::fill_row(std::size_t i, std::span<const double> x, std::span<const double> y,
                             const CubicSpline& kernel) {
  // Everything the loop reads besides x and y in locals: through the stores into the rows the
  // compiler would otherwise reload the rows' addresses and the kernel's constants at every pair.
  const CubicSpline W = kernel;
  const double support2 = W.support() * W.support(), xi = x[i], yi = y[i];
  const std::size_t first = i * slots_, candidates = candidate_count_[i];
  const int* candidate = candidates_.data() + first;
  int* const j_row = neighbour.data() + first;
  double* const rx_row = rx.data() + first;
  double* const ry_row = ry.data() + first;
  double* const w_row = w.data() + first;
  double* const gx_row = gx.data() + first;
  double* const gy_row = gy.data() + first;
  std::size_t k = 0;
  for (std::size_t c = 0; c < candidates; ++c) {
    const int j = candidate[c];
    const auto uj = static_cast<std::size_t>(j);
    const double rxij = xi - x[uj], ryij = yi - y[uj];
    const double r2 = rxij * rxij + ryij * ryij;
    if (r2 >= support2) continue;
    const auto [value, dw_over_r] = W.value_and_gradient_factor(std::sqrt(r2));
    j_row[k] = j;
    rx_row[k] = rxij;
    ry_row[k] = ryij;
    w_row[k] = value;
    gx_row[k] = dw_over_r * rxij;
    gy_row[k] = dw_over_r * ryij;
    ++k;
  }
  count_[i] = k;
}

std::size_t NeighbourList::bytes_per_particle() const {
  return slots_ * (2 * sizeof(int) + 5 * sizeof(double)) + 2 * sizeof(std::size_t) + 2 * sizeof(double);
}

}  // namespace soilsph::sph
