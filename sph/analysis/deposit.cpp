// Deposit metrics: main cluster (union–find over a cell grid), then extents and a surface fit.
#include "sph/analysis/deposit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace soilsph::sph {
namespace {

/// Disjoint sets with path halving and union by size.
class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n), size_(n, 1) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  std::size_t size(std::size_t i) { return size_[find(i)]; }

 private:
  std::vector<std::size_t> parent_, size_;
};

/// Indices of the largest set of particles linked (directly or through others) by distances ≤ link,
/// `axes` their coordinates in the plane (x, y) or in space (x, y, z). Cells of side `link` mean a
/// particle's links are all in its own or the 3^dim − 1 surrounding cells.
template <std::size_t dim>
std::vector<std::size_t> largest_cluster(const std::array<std::span<const double>, dim>& axes, double link) {
  using Cell = std::array<std::int64_t, dim>;
  const std::size_t n = axes[0].size();
  std::array<double, dim> lowest;
  for (std::size_t a = 0; a < dim; ++a) lowest[a] = *std::min_element(axes[a].begin(), axes[a].end());
  std::map<Cell, std::vector<std::size_t>> cells;  // sparse: a far splash does not allocate a grid
  for (std::size_t i = 0; i < n; ++i) {
    Cell cell;
    for (std::size_t a = 0; a < dim; ++a)
      cell[a] = static_cast<std::int64_t>(std::floor((axes[a][i] - lowest[a]) / link));
    cells[cell].push_back(i);
  }
  DisjointSets sets(n);
  const double link2 = link * link;
  const auto linked = [&](std::size_t i, std::size_t j) {
    double r2 = 0.0;
    for (std::size_t a = 0; a < dim; ++a) r2 += (axes[a][i] - axes[a][j]) * (axes[a][i] - axes[a][j]);
    return r2 <= link2;
  };
  constexpr int kNeighbourCells = dim == 2 ? 9 : 27;
  for (const auto& [cell, members] : cells) {
    for (int k = 0; k < kNeighbourCells; ++k) {
      Cell next = cell;
      for (std::size_t a = 0, code = static_cast<std::size_t>(k); a < dim; ++a, code /= 3)
        next[a] += static_cast<std::int64_t>(code % 3) - 1;
      const auto other = cells.find(next);
      if (other == cells.end()) continue;
      for (const std::size_t i : members)
        for (const std::size_t j : other->second)
          if (j > i && linked(i, j)) sets.unite(i, j);
    }
  }
  std::size_t root = 0, best = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (sets.size(i) > best) {
      best = sets.size(i);
      root = sets.find(i);
    }
  }
  std::vector<std::size_t> cluster;
  cluster.reserve(best);
  for (std::size_t i = 0; i < n; ++i) {
    if (sets.find(i) == root) cluster.push_back(i);
  }
  return cluster;
}

/// Top particle of each vertical strip of width `spacing`, strips centred on x = W − k·spacing;
/// key −k: ascending x, the toe first.
std::map<std::int64_t, std::size_t> strip_tops(std::span<const double> x, std::span<const double> y,
                                               const std::vector<std::size_t>& cluster, double fixed_wall_x,
                                               double spacing) {
  std::map<std::int64_t, std::size_t> top;
  for (const std::size_t i : cluster) {
    const auto key = -std::llround((fixed_wall_x - x[i]) / spacing);
    const auto [it, inserted] = top.try_emplace(key, i);
    if (!inserted && y[i] > y[it->second]) it->second = i;
  }
  return top;
}

/// Distance from the fixed wall to the toe-most strip at least `thickness` thick (see deposit.h).
double runout_at_thickness(std::span<const double> x, std::span<const double> y,
                           const std::map<std::int64_t, std::size_t>& top, double fixed_wall_x,
                           double spacing, double thickness) {
  for (const auto& [key, i] : top)  // from the toe
    if (y[i] + spacing >= thickness) return fixed_wall_x - x[i];
  return 0.0;
}

/// Slope angle of the surface between toe and crest (see deposit.h), degrees.
double repose_angle(std::span<const double> x, std::span<const double> y,
                    const std::map<std::int64_t, std::size_t>& top, double height) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [key, i] : top) {
    if (y[i] >= repose_band_high * height) break;   // the crest: the fit stops here
    if (y[i] < repose_band_low * height) continue;  // the thin toe tail
    n += 1;
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  // Least squares y = a + m x: m = (n Σxy − Σx Σy) / (n Σxx − (Σx)²).
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator <= 1e-12 * n * sxx) return 90.0;  // no horizontal extent: a vertical face
  const double slope = (n * sxy - sx * sy) / denominator;
  return std::atan(slope) * 180.0 / std::numbers::pi;
}

}  // namespace

DepositMetrics measure_deposit(std::span<const double> x, std::span<const double> y, double fixed_wall_x,
                               double spacing, double toe_thickness) {
  if (x.empty() || x.size() != y.size()) {
    throw std::invalid_argument("measure_deposit: x and y must be non-empty and of equal length (got " +
                                std::to_string(x.size()) + " and " + std::to_string(y.size()) + ")");
  }
  if (!(spacing > 0) || !std::isfinite(spacing) || !std::isfinite(fixed_wall_x)) {
    throw std::invalid_argument("measure_deposit: spacing must be finite and > 0 and the wall finite");
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw std::invalid_argument("measure_deposit: particle " + std::to_string(i) +
                                  " has a non-finite position");
    }
  }
  const std::vector<std::size_t> cluster = largest_cluster<2>({x, y}, deposit_link_spacings * spacing);
  double min_x = x[cluster.front()], max_y = y[cluster.front()];
  for (const std::size_t i : cluster) {
    min_x = std::min(min_x, x[i]);
    max_y = std::max(max_y, y[i]);
  }
  const auto top = strip_tops(x, y, cluster, fixed_wall_x, spacing);
  return {fixed_wall_x - min_x, max_y, repose_angle(x, y, top, max_y),
          toe_thickness > 0.0 ? runout_at_thickness(x, y, top, fixed_wall_x, spacing, toe_thickness)
                              : std::numeric_limits<double>::quiet_NaN()};
}

DepositMetrics measure_slab_deposit(std::span<const double> x, std::span<const double> y,
                                    std::span<const double> z, double fixed_wall_x, double spacing,
                                    double toe_thickness) {
  if (x.empty() || x.size() != y.size() || x.size() != z.size())
    throw std::invalid_argument("measure_slab_deposit: x, y and z must be non-empty and of equal length");
  if (!(spacing > 0) || !std::isfinite(spacing))
    throw std::invalid_argument("measure_slab_deposit: spacing must be finite and > 0");
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i]))
      throw std::invalid_argument("measure_slab_deposit: particle " + std::to_string(i) +
                                  " has a non-finite position");
  const std::vector<std::size_t> body = largest_cluster<3>({x, y, z}, deposit_link_spacings * spacing);
  std::vector<double> body_x, body_y;
  body_x.reserve(body.size());
  body_y.reserve(body.size());
  for (const std::size_t i : body) body_x.push_back(x[i]), body_y.push_back(y[i]);
  // Linked in space, the body is linked on the plane too (projection shortens every distance):
  // the plane's measure keeps it whole.
  return measure_deposit(body_x, body_y, fixed_wall_x, spacing, toe_thickness);
}

DepositMetrics measure_deposit(std::span<const double> x, std::span<const double> y, const DepositFrame& frame,
                               double spacing) {
  if (x.size() != y.size())
    throw std::invalid_argument("measure_deposit: x and y must be of equal length (got " + std::to_string(x.size()) +
                                " and " + std::to_string(y.size()) + ")");
  if (!frame.defined) {
    constexpr double undefined = std::numeric_limits<double>::quiet_NaN();
    return {undefined, undefined, undefined, undefined};
  }
  std::vector<double> along(x.size()), height(x.size());
  const double floor = dot(frame.up, frame.origin);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec2 p{x[i], y[i]};
    along[i] = -dot(frame.direction, p);
    height[i] = dot(frame.up, p) - floor;
  }
  return measure_deposit(along, height, -dot(frame.direction, frame.origin), spacing, frame.toe_thickness);
}

}  // namespace soilsph::sph
