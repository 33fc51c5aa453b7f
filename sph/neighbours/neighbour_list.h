#pragma once
/// @file
/// The neighbour list: for every particle i, the particles j ≠ i within the kernel support, with the
/// pair quantities every stage needs precomputed once per step: x_i − x_j, W_ij and ∇_i W_ij.
/// Flat arrays with a fixed number of slots per particle (grown when a particle has more neighbours),
/// filled in one parallel pass. Boundary–boundary pairs are left out: no stage uses them (a ghost
/// particle only reads the soil around it).
///
/// Verlet skin: the cell-list search finds the candidates within 2h + s (s = 0.25h) and is
/// repeated only when some particle has moved more than s/2 since the last search (two particles
/// then cannot have come closer than 2h without both having been candidates). Every step the pairs
/// within 2h and their W, ∇W are recomputed from the candidates at the current positions.
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

class NeighbourList {
 public:
  /// Finds the neighbours of every point; points [first_boundary, size) are boundary points, which
  /// must not move. Parallel over particles (OpenMP); reuses its buffers.
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
  /// Cell-list searches done so far (one per build without the skin).
  std::size_t searches() const { return searches_; }

  // Per pair k (i, j = neighbour[k]):
  std::vector<int> neighbour;  ///< j
  std::vector<double> rx, ry;  ///< x_i − x_j (m)
  std::vector<double> w;       ///< W_ij
  std::vector<double> gx, gy;  ///< ∇_i W_ij = dW/dr (x_i − x_j)/r (1/m³)

  static constexpr double kSkinRatio = 0.25;  ///< s/h

 private:
  bool moved_beyond_skin(std::span<const double> x, std::span<const double> y, double skin) const;
  /// One cell-list pass; returns the largest candidate count (above candidate_slots_: grow, redo).
  std::size_t search(std::span<const double> x, std::span<const double> y, double radius,
                     std::size_t first_boundary);
  /// Pairs within the support from the candidates; returns the largest pair count.
  std::size_t fill(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel);

  CellList cells_;
  std::size_t slots_ = 32;            ///< pair slots per particle
  std::size_t candidate_slots_ = 48;  ///< candidate slots per particle
  std::vector<std::size_t> count_, candidate_count_;
  std::vector<int> candidates_;
  std::vector<double> x_ref_, y_ref_;  ///< positions at the last search
  std::size_t searches_ = 0;
};

}  // namespace soilsph::sph
