#include "sph/neighbours/neighbour_list.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <omp.h>
#include <vector>

namespace soilsph::sph {

namespace {
/// |r|² summed from the first axis on (in 2D: rx² + ry², the order the plane's results were made with).
template <int dim>
double squared_norm(const std::array<double, dim>& r) {
  double s = r[0] * r[0];
  for (int d = 1; d < dim; ++d) s += r[static_cast<std::size_t>(d)] * r[static_cast<std::size_t>(d)];
  return s;
}

/// Calls f(cell) for the rows of three cells around c: cy − 1 … cy + 1 (and cz − 1 … cz + 1, the
/// slower index outside), in the cell numbering's order.
template <int dim, class F>
void for_each_stencil_row(const typename CellGrid<dim>::Cell& c, F&& f) {
  typename CellGrid<dim>::Cell row = c;
  if constexpr (dim == 2) {
    for (int dy = -1; dy <= 1; ++dy) row[1] = c[1] + dy, f(row);
  } else {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy) row[1] = c[1] + dy, row[2] = c[2] + dz, f(row);
  }
}
}  // namespace

template <int dim>
  requires(dim == 2 || dim == 3)
void PairList<dim>::build(const Coordinates<dim>& x, const Kernel& kernel, std::size_t first_boundary,
                          std::span<const std::uint64_t> soil_ids) {
  bool needed = false;
#pragma omp single copyprivate(needed)
  needed = search_needed(x);
  if (needed) search(x, kernel, first_boundary, soil_ids);
  const auto n = static_cast<std::ptrdiff_t>(x[0].size());
  kernel.visit([&](const auto& w) {
#pragma omp for schedule(static)
    for (std::ptrdiff_t s = 0; s < n; ++s) fill_row(static_cast<std::size_t>(s), x, w);
  });
}

template <int dim>
  requires(dim == 2 || dim == 3)
bool PairList<dim>::search_needed(const Coordinates<dim>& x) const {
  const std::size_t n = x[0].size();
  if (x_ref_[0].size() != n) return true;
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, dim> moved;
    for (std::size_t d = 0; d < dim; ++d) moved[d] = x[d][i] - x_ref_[d][i];
    if (!(squared_norm<dim>(moved) <= half_skin2_)) return true;  // also for a non-finite position
  }
  return false;
}

template <int dim>
  requires(dim == 2 || dim == 3)
void PairList<dim>::search(const Coordinates<dim>& x, const Kernel& kernel, std::size_t first_boundary,
                           std::span<const std::uint64_t> soil_ids, std::size_t image_begin) {
  const std::size_t n = x[0].size();
  const double radius = kernel.support() + kSkinRatio * kernel.smoothing_length();
  const SearchRadii radii{radius * radius, kernel.support() * kernel.support(),
                          kernel.smoothing_length() * kernel.smoothing_length()};
  std::exception_ptr failure;
#pragma omp single copyprivate(failure)
  {
    try {
      set_binning_order(soil_ids, n);
      cells_.build(x, radius, true, binning_order_);
    } catch (...) {
      failure = std::current_exception();
    }
    candidate_count_.resize(n);
    count_.assign(n, 0);
    row_block_.resize(n);
    row_first_.resize(n);
    blocks_.resize(std::max(blocks_.size(), static_cast<std::size_t>(omp_get_num_threads())));
  }
  if (failure) std::rethrow_exception(failure);  // every thread: the caller's try block catches it
  const auto thread = static_cast<unsigned>(omp_get_thread_num());
  Block& block = blocks_[thread];
  block.candidates.clear();
  const auto rows = static_cast<std::ptrdiff_t>(n);
#pragma omp for schedule(static)
  for (std::ptrdiff_t s = 0; s < rows; ++s)
    search_row(static_cast<std::size_t>(s), x, radii, {first_boundary, image_begin}, block, thread);
  // The pair slots of this thread's rows, grown only (first touched by the thread that fills them).
  const std::size_t slots = block.candidates.size();
  if (block.neighbour.size() < slots) {
    block.neighbour.resize(slots);
    for (auto& a : block.pairs) a.resize(slots);
  }
#pragma omp barrier
#pragma omp single
  {
    const double skin = kSkinRatio * kernel.smoothing_length();
    half_skin2_ = 0.25 * skin * skin;  // (s/2)²
    for (std::size_t d = 0; d < dim; ++d) x_ref_[d].assign(x[d].begin(), x[d].end());
    ++searches_;
  }
}

template <int dim>
  requires(dim == 2 || dim == 3)
void PairList<dim>::set_binning_order(std::span<const std::uint64_t> soil_ids, std::size_t n) {
  binning_order_.clear();
  if (std::is_sorted(soil_ids.begin(), soil_ids.end())) return;  // ids in index order: bin by index
  binning_order_.resize(n);
  std::iota(binning_order_.begin(), binning_order_.end(), std::size_t{0});
  std::sort(binning_order_.begin(), binning_order_.begin() + static_cast<std::ptrdiff_t>(soil_ids.size()),
            [&](std::size_t a, std::size_t b) { return soil_ids[a] < soil_ids[b]; });
}

template <int dim>
  requires(dim == 2 || dim == 3)
void PairList<dim>::search_row(std::size_t i, const Coordinates<dim>& x, const SearchRadii& radii,
                               Parts parts, Block& block, unsigned block_index) {
  struct Candidate {
    double r2;
    int j;
  };
  thread_local std::vector<Candidate> found;  // grows to the largest row once, then reused
  found.clear();
  const bool boundary_i = i >= parts.first_boundary, image_i = i >= parts.image_begin;
  const auto band = [&](double r2) { return static_cast<std::size_t>(r2 >= radii.inner2) + (r2 >= radii.support2); };
  std::array<double, dim> xi;
  for (std::size_t d = 0; d < dim; ++d) xi[d] = x[d][i];
  if (!image_i) for_each_stencil_row<dim>(cells_.cell_of_point(x, i), [&](const typename CellGrid<dim>::Cell& row) {
    const typename CellGrid<dim>::Run run = cells_.row_of_three(row);
    for (std::size_t k = 0; k < run.size; ++k) {
      std::array<double, dim> r;
      for (std::size_t d = 0; d < dim; ++d) r[d] = xi[d] - run.x[d][k];
      const double r2 = squared_norm<dim>(r);
      if (r2 >= radii.search2) continue;
      const int j = run.index[k];
      const auto uj = static_cast<std::size_t>(j);
      if (uj == i || (boundary_i && uj >= parts.first_boundary && uj < parts.image_begin)) continue;
      found.push_back({r2, j});
    }
  });
  const std::size_t first = block.candidates.size();
  row_block_[i] = block_index;
  row_first_[i] = first;
  candidate_count_[i] = found.size();
  block.candidates.resize(first + found.size());
  // In three bands, each in the search's order: within h (the kernel's inner branch), within the
  // support 2h (its outer branch), and the skin beyond. While the candidates move less than the
  // skin, a row's pairs stay nearly a prefix of it and each band takes one branch of the kernel, so
  // the tests of fill_row are predicted. A stable counting partition, O(n): the order is a function
  // of the positions alone (the cell order, then the index), as a sort's would be.
  std::size_t next[3] = {0, 0, 0};
  for (const Candidate& c : found) ++next[band(c.r2)];
  next[2] = next[0] + next[1], next[1] = next[0], next[0] = 0;
  for (const Candidate& c : found) block.candidates[first + next[band(c.r2)]++] = c.j;
}

template <int dim>
  requires(dim == 2 || dim == 3)
template <PairKernel K>
void PairList<dim>::fill_row(std::size_t i, const Coordinates<dim>& x, const K& kernel) {
  // Everything the loop reads in locals, the coordinates' spans too: through the stores into the
  // rows the compiler would otherwise reload the rows' addresses, the kernel's constants and the
  // coordinates' arrays at every pair.
  const K W = kernel;
  const double support2 = W.support() * W.support();
  Block& block = blocks_[row_block_[i]];
  const std::size_t first = row_first_[i], candidates = candidate_count_[i];
  const int* candidate = block.candidates.data() + first;
  int* const j_row = block.neighbour.data() + first;
  double* const w_row = block.pairs[0].data() + first;
  double* const g_row = block.pairs[1].data() + first;
  const Coordinates<dim> xs = x;
  std::array<double, dim> xi;
  for (int d = 0; d < dim; ++d) xi[d] = xs[d][i];
  std::size_t k = 0;
  for (std::size_t c = 0; c < candidates; ++c) {
    const int j = candidate[c];
    const auto uj = static_cast<std::size_t>(j);
    std::array<double, dim> r;
    for (int d = 0; d < dim; ++d) r[d] = xi[d] - xs[d][uj];
    double r2 = r[0] * r[0];
    for (int d = 1; d < dim; ++d) r2 += r[d] * r[d];
    if (r2 >= support2) continue;
    const auto [value, dw_over_r] = W.value_and_gradient_factor(std::sqrt(r2));
    j_row[k] = j;
    w_row[k] = value;
    g_row[k] = dw_over_r;
    ++k;
  }
  count_[i] = k;
}

template <int dim>
  requires(dim == 2 || dim == 3)
std::size_t PairList<dim>::bytes() const {
  // Per slot: a candidate (as allocated) and a pair, its neighbour index and doubles; per particle:
  // the row's place, its two counts and its search position.
  std::size_t slots = 0;
  for (const Block& b : blocks_)
    slots += b.candidates.capacity() * sizeof(int) + b.neighbour.size() * (sizeof(int) + kPairDoubles * sizeof(double));
  const std::size_t per_row = sizeof(unsigned) + 3 * sizeof(std::size_t) + dim * sizeof(double);
  return slots + size() * per_row;
}

template class PairList<2>;
template class PairList<3>;
template void PairList<2>::fill_row(std::size_t, const Coordinates<2>&, const CubicSplineKernel<2>&);
template void PairList<2>::fill_row(std::size_t, const Coordinates<2>&, const WendlandC2Kernel<2>&);
template void PairList<3>::fill_row(std::size_t, const Coordinates<3>&, const CubicSplineKernel<3>&);
template void PairList<3>::fill_row(std::size_t, const Coordinates<3>&, const WendlandC2Kernel<3>&);

}  // namespace soilsph::sph
