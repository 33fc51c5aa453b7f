#pragma once
/// @file
/// The column shorthand: the [scene] keys column_width, column_height, floor_length,
/// wall_withdrawal and boundary_layers describe the paper's column, which this builds as a layout
/// (one box region, a no-slip floor, a free-slip fixed wall on the right and a free-slip removable
/// wall on the left), placing particle centres on the edges of W × H as the paper does (so the block
/// grows with the spacing: docs/validation/resolution.md).
#include "sph/geometry/layout.h"

namespace soilsph::sph {

struct ColumnKeys {
  double width, height;    ///< W, H (m): soil particle centres on [0, W] × [0, H]
  double spacing;          ///< Δp (m)
  double smoothing_length; ///< h (m): the walls reach H + 2h
  double floor_length;     ///< m, the floor from the fixed wall leftwards
  int layers;              ///< ghost layers behind each wall
  bool left_wall_withdrawn;  ///< "instant": the left wall is never there
  double lift_speed = 0.0;   ///< "lift": the left wall rises at this speed from t = 0 (m/s), 0: it stays
};

/// The soil box [−Δp/2, W + Δp/2] × [−Δp/2, H + Δp/2] (the particles' cells) on the lattice from
/// (0, 0); the floor surface y = −Δp/2 from x = W − floor_length − Δp/2 to the fixed wall; the fixed
/// wall x = W + Δp/2 and the removable wall x = −Δp/2 from the floor up to H + 2h + Δp/2. A lifted
/// wall is a gate: it moves up at lift_speed from t = 0 until its lower end has passed H + 2h + Δp
/// (no soil particle reaches it any more), and is removed then.
Layout column_layout(const ColumnKeys& column, const std::string& material);

}  // namespace soilsph::sph
