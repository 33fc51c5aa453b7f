// Deposit metrics: main cluster (union–find over a cell grid), then extents and a surface fit.
#include "sph/analysis/deposit.h"

#include <algorithm>
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

/// Indices of the largest set of particles linked (directly or through others) by distances ≤ link.
/// Cells of side `link` mean a particle's links are all in its own or the 8 surrounding cells.
std::vector<std::size_t> largest_cluster(std::span<const double> x, std::span<const double> y, double link) {
  using Cell = std::pair<std::int64_t, std::int64_t>;
  const double x0 = *std::min_element(x.begin(), x.end()), y0 = *std::min_element(y.begin(), y.end());
  std::map<Cell, std::vector<std::size_t>> cells;  // sparse: a far splash does not allocate a grid
  for (std::size_t i = 0; i < x.size(); ++i) {
    cells[{static_cast<std::int64_t>(std::floor((x[i] - x0) / link)),
           static_cast<std::int64_t>(std::floor((y[i] - y0) / link))}]
        .push_back(i);
  }
  DisjointSets sets(x.size());
  const double link2 = link * link;
  for (const auto& [cell, members] : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto other = cells.find({cell.first + dx, cell.second + dy});
        if (other == cells.end()) continue;
        for (const std::size_t i : members) {
          for (const std::size_t j : other->second) {
            if (j <= i) continue;
            const double rx = x[i] - x[j], ry = y[i] - y[j];
            if (rx * rx + ry * ry <= link2) sets.unite(i, j);
          }
        }
      }
    }
  }
  std::size_t root = 0, best = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (sets.size(i) > best) {
      best = sets.size(i);
      root = sets.find(i);
    }
  }
  std::vector<std::size_t> cluster;
  cluster.reserve(best);
  for (std::size_t i = 0; i < x.size(); ++i) {
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
  const std::vector<std::size_t> cluster = largest_cluster(x, y, deposit_link_spacings * spacing);
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
