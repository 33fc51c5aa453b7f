#pragma once
/// @file
/// Cell-linked list: particles binned into square cells of side ≥ the kernel support, stored as
/// flat arrays (a counting sort), so that a particle's neighbours lie in its own and the 8
/// surrounding cells. Cells are numbered row by row, so the three cells (cx − 1 … cx + 1, cy) of a
/// row are one contiguous run of the sorted particles (`row_of_three`), which also holds their
/// positions in that order: a search reads them as a stream instead of gathering x[j], y[j].
/// Rebuilt from scratch every step: it costs O(N) and the buffers are reused.
#include <span>
#include <vector>

namespace soilsph::sph {

class CellList {
 public:
  /// Bins the points (x[i], y[i]) into cells of side `cell_size`; with `keep_positions` also copies
  /// their positions in cell order for row_of_three().
  void build(std::span<const double> x, std::span<const double> y, double cell_size, bool keep_positions = false);

  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }
  /// Cell coordinates of a point (clamped to the grid).
  int cell_x(double x) const;
  int cell_y(double y) const;
  /// The particles in cell (cx, cy); empty outside the grid.
  std::span<const int> particles_in(int cx, int cy) const;

  /// The particles of cells cx − 1 … cx + 1 (those inside the grid) of row cy, with their positions
  /// (after a build that kept them).
  struct Run {
    const int* index;
    const double *x, *y;
    std::size_t size;
  };
  Run row_of_three(int cx, int cy) const;

 private:
  double x0_ = 0.0, y0_ = 0.0, inv_size_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_start_;  ///< ncells + 1 offsets into sorted_
  std::vector<int> sorted_;      ///< particle indices grouped by cell
  std::vector<double> sorted_x_, sorted_y_;  ///< their positions, in the same order
  std::vector<int> cell_of_;     ///< cell of each particle
  std::vector<int> cursor_;      ///< fill position per cell during build
};

}  // namespace soilsph::sph
