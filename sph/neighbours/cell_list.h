#pragma once
/// @file
/// Cell-linked list in 2 or 3 dimensions: particles binned into square (cubic) cells of side ≥ the
/// kernel support, stored as flat arrays (a counting sort), so that a particle's neighbours lie in
/// its own and the 3^dim − 1 surrounding cells. Cells are numbered with x running fastest, then y,
/// then z, so the three cells (cx − 1 … cx + 1) of one row of fixed (cy[, cz]) are one contiguous
/// run of the sorted particles (`row_of_three`), which also holds their positions in that order: a
/// search reads them as a stream instead of gathering x[j], y[j]. A particle's stencil is 3 such
/// runs in 2D and 9 in 3D. Rebuilt from scratch at every search: it costs O(N) and the buffers are
/// reused.
///
/// Where the grid lies: by default its first cell starts at the particles' smallest coordinates
/// (the bounding box). After anchor_at(o), cell k of axis d covers [o_d + k s, o_d + (k + 1) s) for
/// every integer k, whatever particles are present: the cell of a particle, and so the order in
/// which a search meets its neighbours, then depends on its position alone, not on which other
/// particles one process holds (a domain decomposition gets the pair sums of one process).
///
/// Within a cell the points keep the order they are binned in (a stable counting sort): the index
/// by default; the neighbour list bins the soil by id (neighbour_list.h), so that a cell's content
/// does not depend on the order the particles are stored in.
#include <array>
#include <optional>
#include <span>
#include <vector>

namespace soilsph::sph {

/// The coordinate arrays of a set of points: x, y[, z], each one value per point.
template <int dim>
using Coordinates = std::array<std::span<const double>, dim>;

template <int dim>
  requires(dim == 2 || dim == 3)
class CellGrid {
 public:
  using Cell = std::array<int, dim>;

  /// Anchors the grid at a fixed origin (see the file comment); without it, at the bounding box.
  void anchor_at(const std::array<double, dim>& origin) { anchor_ = origin; }

  /// Bins the points x into cells of side `cell_size`; with `keep_positions` also copies their
  /// positions in cell order for row_of_three(). Within a cell the points lie in the order they are
  /// binned: `order` (a permutation of the indices), or by index without it. Throws
  /// std::runtime_error for a position that is not finite or points spread over too large a domain.
  void build(const Coordinates<dim>& x, double cell_size, bool keep_positions = false,
             std::span<const std::size_t> order = {});

  /// Cells along axis d.
  int cells(int d) const { return n_[d]; }
  /// The cell of coordinate v along axis d (clamped to the grid).
  int cell(int d, double v) const;
  /// The cell of point i of the last build.
  Cell cell_of_point(const Coordinates<dim>& x, std::size_t i) const {
    Cell c;
    for (int d = 0; d < dim; ++d) c[d] = cell(d, x[d][i]);
    return c;
  }
  /// The particles in cell c; empty outside the grid.
  std::span<const int> particles_in(const Cell& c) const;

  /// The particles of cells c[0] − 1 … c[0] + 1 (those inside the grid) of the row through c, with
  /// their positions (after a build that kept them).
  struct Run {
    const int* index;
    std::array<const double*, dim> x;
    std::size_t size;
  };
  Run row_of_three(const Cell& c) const;

 private:
  std::optional<std::array<double, dim>> anchor_;
  std::array<double, dim> origin_{};  ///< the anchor, or the smallest coordinates
  std::array<int, dim> offset_{};     ///< the grid's first cell counted from origin_ (0 unanchored)
  std::array<int, dim> n_{};          ///< cells along each axis
  double inv_size_ = 1.0;
  std::vector<int> cell_start_;  ///< ncells + 1 offsets into sorted_
  std::vector<int> sorted_;      ///< particle indices grouped by cell
  std::array<std::vector<double>, dim> sorted_x_;  ///< their positions, in the same order
  std::vector<int> cell_of_;     ///< cell of each particle
  std::vector<int> cursor_;      ///< fill position per cell during build

  std::size_t index_of(const Cell& c) const {
    std::size_t k = static_cast<std::size_t>(c[dim - 1]);
    for (int d = dim - 2; d >= 0; --d) k = k * static_cast<std::size_t>(n_[d]) + static_cast<std::size_t>(c[d]);
    return k;
  }
};

/// The plane's cell list (the 2D solver's).
using CellList = CellGrid<2>;

}  // namespace soilsph::sph
