#pragma once
/// @file
/// Shape of the final deposit of a column collapse: runout, height and repose angle.
///
/// Geometry (the agreed scene): the fixed wall is at x = W on the right, the soil flows towards −x
/// on the floor y = 0. Definitions (docs/reference/output-formats.md, with the reasons):
/// - The deposit is the largest cluster of particles linked by distances ≤ 2·spacing; isolated
///   splashed particles or small groups farther than that from the main body are ignored.
/// - runout_m = W − (smallest x of the deposit): the L∞ of Lube et al. (2005) measured from the
///   fixed wall, on particle centres (with particles on the column edges it starts at L0 = W).
/// - height_m = largest y of the deposit (particle centres; starts at H).
/// - repose_angle_deg: the free surface is the top particle of each vertical strip of width
///   `spacing`; the angle is atan of the least-squares slope of the surface points between the toe
///   and the crest (the first strip reaching 90 % of height_m), keeping those higher than 10 % of
///   height_m so that the thin toe tail and the rounded shoulder do not bias it. If that leaves
///   fewer than two points the face is vertical and the angle is 90°.
/// - runout_thick_m (with a toe thickness t > 0): W − x of the toe-most surface strip whose
///   deposit is at least t thick, the thickness of a strip being its top particle's y + spacing
///   (the floor surface lies half a spacing below the first row, the free surface half a spacing
///   above the top particle). Unlike runout_m it ignores a toe thinner than t, whose length depends
///   on the resolution (a layer one or two particles thick); the collapse takes t = H0/10, which
///   every shipped resolution resolves with at least two particles (docs/validation/resolution.md).
#include <span>

#include "sph/geometry/vec2.h"

namespace soilsph::sph {

/// Runout, height and repose angle of a deposit (SI, degrees).
struct DepositMetrics {
  double runout_m, height_m, repose_angle_deg;
  double runout_thick_m;  ///< NaN unless a toe thickness is given
};

/// Link distance between particles of one deposit, in particle spacings.
inline constexpr double deposit_link_spacings = 2.0;
/// Height band of the surface points the repose angle is fitted on, as fractions of the height.
inline constexpr double repose_band_low = 0.1, repose_band_high = 0.9;

/// Where a scene's deposit is measured from ([deposit], docs/reference/scenes.md): runout grows along
/// the unit `direction` from `origin`, height along `up` (the unit normal of `direction` against gravity) above
/// the origin, and the repose angle is the surface's slope in that frame. The column's frame is
/// origin (W, 0), direction (−1, 0), up (0, 1): the definitions above, to the bit.
///
/// A scene of [[regions]] without [deposit] has no frame of its own (its soil need not stand against a
/// wall on a floor): its frame is undefined and its measures are NaN, rather than numbers measured
/// from a column's wall that the scene does not have.
struct DepositFrame {
  Vec2 origin;
  Vec2 direction{-1.0, 0.0};
  Vec2 up{0.0, 1.0};
  double toe_thickness = 0.0;  ///< t of runout_thick_m (m); 0: not measured
  bool defined = true;         ///< false: no frame; every measure is NaN
};

/// x, y of the soil particles; fixed_wall_x = W; spacing = initial particle spacing (for robust
/// measures that ignore isolated, splashed particles); toe_thickness t for runout_thick_m (0: not
/// measured). Throws std::invalid_argument on empty or mismatched input or a non-positive spacing.
DepositMetrics measure_deposit(std::span<const double> x, std::span<const double> y, double fixed_wall_x,
                               double spacing, double toe_thickness = 0.0);

/// The deposit of a slab (the column extruded along z between two symmetry planes): the measures
/// above of the particles of the largest cluster linked in space (x, y, z), taken onto the plane.
/// Linked on the plane instead, the slab's layers would link particles that lie up to the slab's
/// width apart across it, and a toe of lone particles in different layers would read as one body.
/// Throws std::invalid_argument as measure_deposit does, and on a non-finite z.
DepositMetrics measure_slab_deposit(std::span<const double> x, std::span<const double> y,
                                    std::span<const double> z, double fixed_wall_x, double spacing,
                                    double toe_thickness = 0.0);

/// The same in `frame` (NaN throughout if the frame is undefined): the particles are taken to the
/// coordinates (−direction·x, up·(x − origin)), in which the frame's origin is a fixed wall at
/// −direction·origin on the floor y = 0. The rotation alone (no shift along the flow) keeps the
/// column's numbers bit-identical.
DepositMetrics measure_deposit(std::span<const double> x, std::span<const double> y, const DepositFrame& frame,
                               double spacing);

}  // namespace soilsph::sph
