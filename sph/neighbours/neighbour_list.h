#pragma once
/// @file
/// The neighbour list: for every particle i, the particles j ≠ i within the kernel support, in a
/// compressed-row layout (flat arrays), with the pair quantities every stage needs precomputed once
/// per step: x_i − x_j, W_ij and ∇_i W_ij. Rebuilt every step (no skin): the positions change every
/// step and a rebuild costs about as much as one stage, so a Verlet skin would save little.
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

class NeighbourList {
 public:
  /// Finds the neighbours of every point; parallel over particles (OpenMP). Reuses its buffers.
  void build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel);

  std::size_t size() const { return offsets_.empty() ? 0 : offsets_.size() - 1; }
  /// Pairs of particle i are [begin(i), end(i)).
  std::size_t begin(std::size_t i) const { return offsets_[i]; }
  std::size_t end(std::size_t i) const { return offsets_[i + 1]; }
  std::size_t pair_count() const { return offsets_.empty() ? 0 : offsets_.back(); }

  // Per pair k (i, j = neighbour[k]):
  std::vector<int> neighbour;  ///< j
  std::vector<double> rx, ry;  ///< x_i − x_j (m)
  std::vector<double> w;       ///< W_ij
  std::vector<double> gx, gy;  ///< ∇_i W_ij = dW/dr (x_i − x_j)/r (1/m³)

 private:
  CellList cells_;
  std::vector<std::size_t> offsets_;
};

}  // namespace soilsph::sph
