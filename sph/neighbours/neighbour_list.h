#pragma once
/// @file
/// The neighbour list: for every particle i, the particles j ≠ i within the kernel support, with the
/// pair quantities every stage needs precomputed once per step: x_i − x_j, W_ij and ∇_i W_ij.
/// Flat arrays with a fixed number of slots per particle (grown when a particle has more candidates
/// than any before). Boundary–boundary pairs are left out: no stage uses them (a ghost particle only
/// reads the soil around it).
///
/// Verlet skin: the cell-list search finds the candidates within 2h + s (s = 0.25h) and is
/// repeated only when some particle has moved more than s/2 since the last search (two particles
/// then cannot have come closer than 2h without both having been candidates). Every step the pairs
/// within 2h and their W, ∇W are recomputed from the candidates at the current positions, one row
/// (particle) at a time, so that the solver can fuse that pass with the work on the same particle.
/// A row has as many pair slots as candidate slots, so filling it never overflows. Stored rather
/// than evaluated again in each of the passes that read them: measured 15 % faster per step
/// (docs/notes/performance-log.md).
///
/// Threading: search() and build() use orphaned OpenMP work-sharing, so they are called by every
/// thread of an enclosing parallel region (the solver's one region per run) or, outside any region,
/// by one thread, which then does all the work.
#include <atomic>
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

class NeighbourList {
 public:
  /// Finds the neighbours of every point; points [first_boundary, size) are boundary points, which
  /// must not move. Searches only when search_needed(); then fills every row.
  void build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
             std::size_t first_boundary);
  /// All points are soil.
  void build(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel) {
    build(x, y, kernel, x.size());
  }

  /// True before the first search, for a different point count, or when a point has moved more
  /// than half the skin since the last search (serial; O(n)).
  bool search_needed(std::span<const double> x, std::span<const double> y) const;
  /// The cell-list search for candidates within 2h + s. Throws std::runtime_error for a position
  /// that is not finite or points spread over too large a domain (in the calling thread that does
  /// the cell binning; call from a try block inside a parallel region).
  void search(std::span<const double> x, std::span<const double> y, const CubicSpline& kernel,
              std::size_t first_boundary);
  /// The pairs of particle i within the support, from its candidates (no synchronisation).
  void fill_row(std::size_t i, std::span<const double> x, std::span<const double> y,
                const CubicSpline& kernel);

  /// One pair (i, j) within the support.
  struct Pair {
    std::size_t j;
    double rx, ry;  ///< x_i − x_j (m)
    double w;       ///< W_ij
    double gx, gy;  ///< ∇_i W_ij = dW/dr (x_i − x_j)/r (1/m³)
  };
  /// Number of pairs of particle i.
  std::size_t pair_count(std::size_t i) const { return count_[i]; }
  /// The pairs of particle i as contiguous arrays (pair k: neighbour j[k], x_i − x_j = (rx[k], ry[k]),
  /// W w[k], ∇_i W (gx[k], gy[k])), for loops the compiler vectorises across pairs.
  struct Row {
    const int* j;
    const double *rx, *ry, *w, *gx, *gy;
    std::size_t size;
  };
  Row row(std::size_t i) const {
    const std::size_t k = i * slots_;
    return {neighbour.data() + k, rx.data() + k, ry.data() + k, w.data() + k,
            gx.data() + k,        gy.data() + k, count_[i]};
  }
  /// Calls f(pair) for every pair of particle i, as filled by fill_row().
  template <class F>
  void for_each_pair(std::size_t i, F&& f) const {
    const Row r = row(i);
    for (std::size_t k = 0; k < r.size; ++k)
      f(Pair{static_cast<std::size_t>(r.j[k]), r.rx[k], r.ry[k], r.w[k], r.gx[k], r.gy[k]});
  }

  std::size_t size() const { return count_.size(); }
  /// The positions of the last search (a resumed run searches from them again to get the same
  /// candidates in the same order).
  const std::vector<double>& search_x() const { return x_ref_; }
  const std::vector<double>& search_y() const { return y_ref_; }
  /// Cell-list searches done so far.
  std::size_t searches() const { return searches_; }
  /// Bytes held per particle by the list (pairs and candidates).
  std::size_t bytes_per_particle() const;

  static constexpr double kSkinRatio = 0.25;  ///< s/h

 private:
  // Per pair k (i, j = neighbour[k]):
  std::vector<int> neighbour;  ///< j
  std::vector<double> rx, ry;  ///< x_i − x_j (m)
  std::vector<double> w;       ///< W_ij
  std::vector<double> gx, gy;  ///< ∇_i W_ij = dW/dr (x_i − x_j)/r (1/m³)

  /// Squares of the search radius 2h + s, the support 2h and h.
  struct SearchRadii {
    double search2, support2, inner2;
  };
  /// Candidates of particle i within the search radius; returns how many there are (all of them,
  /// even beyond the slots, which then must grow).
  std::size_t search_row(std::size_t i, std::span<const double> x, std::span<const double> y,
                         const SearchRadii& radii, std::size_t first_boundary);

  CellList cells_;
  std::size_t slots_ = 48;  ///< candidate (= pair) slots per particle
  std::vector<std::size_t> count_, candidate_count_;
  std::vector<int> candidates_;
  std::vector<double> x_ref_, y_ref_;  ///< positions at the last search
  double half_skin2_ = 0.0;            ///< (s/2)²
  std::size_t searches_ = 0;
  std::atomic<std::size_t> most_candidates_{0};  ///< largest row found beyond the slots (0: none)
};

}  // namespace soilsph::sph
