#pragma once
/// @file
/// The neighbour list: for every particle i, the particles j ≠ i within the kernel support, with the
/// pair quantities every stage needs precomputed once per step: x_i − x_j, W_ij and ∇_i W_ij.
/// Flat arrays with a fixed number of slots per particle (grown when a particle has more neighbours),
/// so that it is filled in one parallel pass. Boundary–boundary pairs are left out: no stage uses
/// them (a ghost particle only reads the soil around it).
/// Rebuilt every step (no Verlet skin): the pair quantities change every step anyway, and the
/// search is a cell-list sweep over the 3 × 3 cells around each particle.
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

class NeighbourList {
 public:
  /// Finds the neighbours of every point; points [first_boundary, size) are boundary points.
  /// Parallel over particles (OpenMP); reuses its buffers.
  void build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
             std::size_t first_boundary);
  /// All points are soil.
  void build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel) {
    build(x, y, kernel, x.size());
  }

  std::size_t size() const { return count_.size(); }
  /// Pairs of particle i are [begin(i), end(i)).
  std::size_t begin(std::size_t i) const { return i * slots_; }
  std::size_t end(std::size_t i) const { return i * slots_ + count_[i]; }

  // Per pair k (i, j = neighbour[k]):
  std::vector<int> neighbour;  ///< j
  std::vector<double> rx, ry;  ///< x_i − x_j (m)
  std::vector<double> w;       ///< W_ij
  std::vector<double> gx, gy;  ///< ∇_i W_ij = dW/dr (x_i − x_j)/r (1/m³)

 private:
  /// One pass; returns the largest neighbour count found (more than slots_ means: grow and redo).
  std::size_t fill(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
                   std::size_t first_boundary);

  CellList cells_;
  std::size_t slots_ = 32;  ///< pair slots per particle
  std::vector<std::size_t> count_;
};

}  // namespace soilsph::sph
