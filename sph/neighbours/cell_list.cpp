#include "sph/neighbours/cell_list.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace soilsph::sph {

void CellList::build(std::span<const double> x, std::span<const double> y, double cell_size, bool keep_positions) {
  const std::size_t n = x.size();
  if (n == 0) {
    nx_ = ny_ = 0;
    return;
  }
  const auto [xmin, xmax] = std::minmax_element(x.begin(), x.end());
  const auto [ymin, ymax] = std::minmax_element(y.begin(), y.end());
  if (!std::isfinite(*xmin + *xmax + *ymin + *ymax))
    throw std::runtime_error("neighbour search: a particle position is not finite");
  x0_ = *xmin;
  y0_ = *ymin;
  inv_size_ = 1.0 / cell_size;
  nx_ = static_cast<int>((*xmax - x0_) * inv_size_) + 1;
  ny_ = static_cast<int>((*ymax - y0_) * inv_size_) + 1;
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  if (cells > 64 * n + 1024)
    throw std::runtime_error("neighbour search: particles spread over too large a domain");

  cell_start_.assign(cells + 1, 0);
  cell_of_.resize(n);
  sorted_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int c = cell_y(y[i]) * nx_ + cell_x(x[i]);
    cell_of_[i] = c;
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) sorted_[cursor_[cell_of_[i]]++] = static_cast<int>(i);
  if (!keep_positions) return;
  sorted_x_.resize(n);
  sorted_y_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(sorted_[k]);
    sorted_x_[k] = x[i], sorted_y_[k] = y[i];
  }
}

CellList::Run CellList::row_of_three(int cx, int cy) const {
  if (cy < 0 || cy >= ny_) return {nullptr, nullptr, nullptr, 0};
  const int first = cy * nx_ + std::max(cx - 1, 0), last = cy * nx_ + std::min(cx + 1, nx_ - 1);
  const auto begin = static_cast<std::size_t>(cell_start_[first]), end = static_cast<std::size_t>(cell_start_[last + 1]);
  return {sorted_.data() + begin, sorted_x_.data() + begin, sorted_y_.data() + begin, end - begin};
}

int CellList::cell_x(double x) const {
  return std::clamp(static_cast<int>((x - x0_) * inv_size_), 0, nx_ - 1);
}
int CellList::cell_y(double y) const {
  return std::clamp(static_cast<int>((y - y0_) * inv_size_), 0, ny_ - 1);
}

std::span<const int> CellList::particles_in(int cx, int cy) const {
  if (cx < 0 || cy < 0 || cx >= nx_ || cy >= ny_) return {};
  const int c = cy * nx_ + cx;
  return {sorted_.data() + cell_start_[c], static_cast<std::size_t>(cell_start_[c + 1] - cell_start_[c])};
}

}  // namespace soilsph::sph
