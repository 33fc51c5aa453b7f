#include "sph/neighbours/cell_list.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace soilsph::sph {

template <int dim>
  requires(dim == 2 || dim == 3)
void CellGrid<dim>::build(const Coordinates<dim>& x, double cell_size, bool keep_positions,
                          std::span<const std::size_t> order) {
  const std::size_t n = x[0].size();
  if (n == 0) {
    n_.fill(0);
    return;
  }
  inv_size_ = 1.0 / cell_size;
  std::size_t cells = 1;
  for (int d = 0; d < dim; ++d) {
    const auto [lo, hi] = std::minmax_element(x[d].begin(), x[d].end());
    if (!std::isfinite(*lo + *hi)) throw std::runtime_error("neighbour search: a particle position is not finite");
    // Anchored: the fixed grid's cells, counted from the one of the smallest coordinate (an integer
    // offset, so that a point's cell is computed alike whatever the bounding box).
    origin_[d] = anchor_ ? (*anchor_)[d] : *lo;
    const double first = std::floor((*lo - origin_[d]) * inv_size_), last = std::floor((*hi - origin_[d]) * inv_size_);
    if (!(last - first < 1e9 && std::abs(first) < 1e9))
      throw std::runtime_error("neighbour search: particles spread over too large a domain");
    offset_[d] = static_cast<int>(first);
    n_[d] = static_cast<int>(last - first) + 1;
    cells *= static_cast<std::size_t>(n_[d]);
  }
  if (cells > 64 * n + 1024) throw std::runtime_error("neighbour search: particles spread over too large a domain");

  cell_start_.assign(cells + 1, 0);
  cell_of_.resize(n);
  sorted_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<int>(index_of(cell_of_point(x, i)));
    cell_of_[i] = c;
    ++cell_start_[static_cast<std::size_t>(c) + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order.empty() ? k : order[k];
    sorted_[static_cast<std::size_t>(cursor_[static_cast<std::size_t>(cell_of_[i])]++)] = static_cast<int>(i);
  }
  if (!keep_positions) return;
  for (int d = 0; d < dim; ++d) {
    sorted_x_[d].resize(n);
    for (std::size_t k = 0; k < n; ++k) sorted_x_[d][k] = x[d][static_cast<std::size_t>(sorted_[k])];
  }
}

template <int dim>
  requires(dim == 2 || dim == 3)
typename CellGrid<dim>::Run CellGrid<dim>::row_of_three(const Cell& c) const {
  for (int d = 1; d < dim; ++d)
    if (c[d] < 0 || c[d] >= n_[d]) return {nullptr, {}, 0};
  Cell first = c, last = c;
  first[0] = std::max(c[0] - 1, 0), last[0] = std::min(c[0] + 1, n_[0] - 1);
  const auto begin = static_cast<std::size_t>(cell_start_[index_of(first)]),
             end = static_cast<std::size_t>(cell_start_[index_of(last) + 1]);
  Run run{sorted_.data() + begin, {}, end - begin};
  for (int d = 0; d < dim; ++d) run.x[d] = sorted_x_[d].data() + begin;
  return run;
}

template <int dim>
  requires(dim == 2 || dim == 3)
int CellGrid<dim>::cell(int d, double v) const {
  // floor: below an anchored grid's origin the cell index is negative before clamping.
  return std::clamp(static_cast<int>(std::floor((v - origin_[d]) * inv_size_)) - offset_[d], 0, n_[d] - 1);
}

template <int dim>
  requires(dim == 2 || dim == 3)
std::span<const int> CellGrid<dim>::particles_in(const Cell& c) const {
  for (int d = 0; d < dim; ++d)
    if (c[d] < 0 || c[d] >= n_[d]) return {};
  const std::size_t k = index_of(c);
  return {sorted_.data() + cell_start_[k], static_cast<std::size_t>(cell_start_[k + 1] - cell_start_[k])};
}

template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace soilsph::sph
