#pragma once
/// @file
/// The neighbour list, in 2 or 3 dimensions: for every particle i, the particles j ≠ i within the
/// kernel support, with the pair quantities the stages need precomputed once per step, in flat
/// arrays (see Storage). Boundary–boundary pairs are left out: no stage uses them (a ghost particle only reads
/// the soil around it), except that a ghost's row lists the soil's mirror images too, which stand
/// for soil behind a symmetry plane, and an image has no row.
///
/// A pair row holds j, W_ij and dW/dr / r (20 B a pair); a pass takes x_i − x_j from the positions
/// and ∇_i W_ij = dW/dr / r · (x_i − x_j). Storing x_i − x_j and ∇_i W_ij as well (44 B a pair in
/// 2D) saves those products but makes a large run stream more than twice the bytes from memory on
/// every pass over the rows; at 10⁶ particles the rows, not the arithmetic, set the step's pace
/// (docs/performance.md, "Cost against the particle count"). In 2D ~21 pairs a particle at
/// h = 1.3Δp; in 3D ~74, and 92 candidates within the search radius in the lattice, which keeps a
/// soil particle's row near 2.3 KB (bytes()).
///
/// Storage: each row holds exactly its candidates (and as many pair slots), in the block of the
/// thread that searched it, so a ghost far from the soil (no candidates: boundary–boundary pairs are
/// left out) costs nothing but its row's place, and a crowded row needs no slots reserved for every
/// other row. The rows of one thread lie back to back in the search's order; a row is found through
/// its block and first slot.
///
/// Verlet skin: the cell-list search finds the candidates within 2h + s (s = 0.25h) and is
/// repeated only when some particle has moved more than s/2 since the last search (two particles
/// then cannot have come closer than 2h without both having been candidates). Every step the pairs
/// within 2h and their kernel values are recomputed from the candidates at the current positions,
/// one row (particle) at a time, so that the solver can fuse that pass with the work on the same
/// particle. A row has as many pair slots as candidate slots, so filling it never overflows. Stored
/// rather than evaluated again in each of the passes that read them: measured 15 % faster per step
/// in 2D (docs/notes/performance-log.md).
///
/// Threading: search() and build() use orphaned OpenMP work-sharing, so they are called by every
/// thread of an enclosing parallel region (the solver's one region per run) or, outside any region,
/// by one thread, which then does all the work.
#include <array>
#include <concepts>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

/// A kernel of one shape (sph/kernel.h), which a row's fill evaluates at every pair.
template <class K>
concept PairKernel = requires(const K& k, double r) {
  { k.value_and_gradient_factor(r) } -> std::same_as<ValueAndGradientFactor>;
  { k.support() } -> std::same_as<double>;
};

/// The pairs a row stores (see the file comment), in either dimension.
struct PairRow {
  /// One pair (i, j) within the support.
  struct Pair {
    std::size_t j;
    double w;          ///< W_ij
    double dw_over_r;  ///< dW/dr / r at r = |x_i − x_j| (1/m^{dim+3}): ∇_i W_ij is it times x_i − x_j
  };
  /// The pairs of particle i as contiguous arrays (pair k: neighbour j[k], W w[k], dW/dr / r
  /// dw_over_r[k]), for loops the compiler vectorises across pairs.
  struct Row {
    const int* j;
    const double *w, *dw_over_r;
    std::size_t size;
  };
};

template <int dim>
  requires(dim == 2 || dim == 3)
class PairList {
 public:
  using Kernel = SmoothingKernel<dim>;
  using Pair = PairRow::Pair;
  using Row = PairRow::Row;

  /// Anchors the search's cell grid at a fixed origin (neighbours/cell_list.h): the candidates'
  /// order then depends on the positions alone.
  void anchor_cells_at(const std::array<double, dim>& origin) { cells_.anchor_at(origin); }

  /// Finds the neighbours of every point; points [first_boundary, size) are boundary points, which
  /// must not move. Searches only when search_needed(); then fills every row. `soil_ids` (one per
  /// soil point, or none: the indices) order the soil within a cell (see search()).
  void build(const Coordinates<dim>& x, const Kernel& kernel, std::size_t first_boundary,
             std::span<const std::uint64_t> soil_ids = {});
  /// True before the first search, for a different point count, or when a point has moved more
  /// than half the skin since the last search (serial; O(n)).
  bool search_needed(const Coordinates<dim>& x) const;
  /// The cell-list search for candidates within 2h + s. Points [image_begin, size) are mirror images
  /// (stages/mirror_images.h): boundary points that are candidates of every row but have no row of
  /// their own (their values are copied, not summed). A row lists its candidates by cell, and
  /// within a cell the soil by `soil_ids` (one per soil point; none: the indices), then the
  /// boundary by index: the rows, and so every sum over them, depend on the positions and ids alone,
  /// not on the order the soil is stored in. Throws std::runtime_error for a position that is not
  /// finite or points spread over too large a domain (in the calling thread that does the cell
  /// binning; call from a try block inside a parallel region).
  void search(const Coordinates<dim>& x, const Kernel& kernel, std::size_t first_boundary,
              std::span<const std::uint64_t> soil_ids = {},
              std::size_t image_begin = std::numeric_limits<std::size_t>::max());
  /// The pairs of particle i within the support, from its candidates (no synchronisation), with a
  /// concrete kernel (a pass takes it from SmoothingKernel::visit outside its loop).
  template <PairKernel K>
  void fill_row(std::size_t i, const Coordinates<dim>& x, const K& kernel);

  // The plane's calls with the coordinates apart (the 2D solver's).
  void build(std::span<const double> x, std::span<const double> y, const Kernel& kernel, std::size_t first_boundary)
    requires(dim == 2)
  {
    build({x, y}, kernel, first_boundary);
  }
  /// All points are soil.
  void build(std::span<const double> x, std::span<const double> y, const Kernel& kernel)
    requires(dim == 2)
  {
    build({x, y}, kernel, x.size());
  }
  bool search_needed(std::span<const double> x, std::span<const double> y) const
    requires(dim == 2)
  {
    return search_needed(Coordinates<2>{x, y});
  }
  void search(std::span<const double> x, std::span<const double> y, const Kernel& kernel, std::size_t first_boundary)
    requires(dim == 2)
  {
    search({x, y}, kernel, first_boundary);
  }
  template <PairKernel K>
  void fill_row(std::size_t i, std::span<const double> x, std::span<const double> y, const K& kernel)
    requires(dim == 2)
  {
    fill_row(i, {x, y}, kernel);
  }

  /// Number of pairs of particle i.
  std::size_t pair_count(std::size_t i) const { return count_[i]; }
  Row row(std::size_t i) const {
    const Block& b = blocks_[row_block_[i]];
    const std::size_t k = row_first_[i];
    return {b.neighbour.data() + k, b.pairs[0].data() + k, b.pairs[1].data() + k, count_[i]};
  }
  /// Calls f(pair) for every pair of particle i, as filled by fill_row(); always inlined, so that f
  /// is too (stages/pair_vectors.h).
  template <class F>
  [[gnu::always_inline]] void for_each_pair(std::size_t i, F&& f) const {
    const Row r = row(i);
    for (std::size_t k = 0; k < r.size; ++k) f(Pair{static_cast<std::size_t>(r.j[k]), r.w[k], r.dw_over_r[k]});
  }

  std::size_t size() const { return count_.size(); }
  /// The positions of the last search along axis d (a resumed run searches from them again to get
  /// the same candidates in the same order).
  const std::vector<double>& search_positions(int d) const { return x_ref_[static_cast<std::size_t>(d)]; }
  const std::vector<double>& search_x() const { return x_ref_[0]; }
  const std::vector<double>& search_y() const { return x_ref_[1]; }
  /// Cell-list searches done so far.
  std::size_t searches() const { return searches_; }
  /// Bytes held by the list: candidates, pairs and the rows' places, counts and search positions.
  std::size_t bytes() const;
  /// bytes() over the particles: the mean over soil and ghosts, whose rows differ in length.
  std::size_t bytes_per_particle() const { return size() == 0 ? 0 : bytes() / size(); }

  static constexpr double kSkinRatio = 0.25;  ///< s/h
  /// The doubles stored per pair: W and dW/dr / r.
  static constexpr int kPairDoubles = 2;

 private:
  /// The rows one thread searched, back to back: candidate slots, and for pair k of a row (i,
  /// j = neighbour[k]) j and the kPairDoubles arrays of PairRow, as many slots as candidates.
  struct Block {
    std::vector<int> candidates, neighbour;
    std::array<std::vector<double>, kPairDoubles> pairs;
  };

  /// Squares of the search radius 2h + s, the support 2h and h.
  struct SearchRadii {
    double search2, support2, inner2;
  };
  /// Where the boundary points and, among them, the mirror images begin.
  struct Parts {
    std::size_t first_boundary, image_begin;
  };
  /// Appends the candidates of particle i within the search radius to `block` and records the row's
  /// place.
  void search_row(std::size_t i, const Coordinates<dim>& x, const SearchRadii& radii, Parts parts, Block& block,
                  unsigned block_index);

  /// The order the points are binned in when the soil's ids are not increasing: the soil by id,
  /// then the boundary; empty when the ids are (the indices' order is theirs).
  void set_binning_order(std::span<const std::uint64_t> soil_ids, std::size_t n);

  CellGrid<dim> cells_;
  std::vector<std::size_t> binning_order_;
  std::vector<Block> blocks_;               ///< one per thread of the searches so far
  std::vector<unsigned> row_block_;         ///< the block holding row i
  std::vector<std::size_t> row_first_;      ///< row i's first slot in its block
  std::vector<std::size_t> count_, candidate_count_;
  std::array<std::vector<double>, dim> x_ref_;  ///< positions at the last search
  double half_skin2_ = 0.0;                     ///< (s/2)²
  std::size_t searches_ = 0;
};

/// The plane-strain solver's neighbour list.
using NeighbourList = PairList<2>;

}  // namespace soilsph::sph
