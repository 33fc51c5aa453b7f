#pragma once
/// @file
/// The deposit of an axisymmetric column collapse: runout radius from the axis (mean over azimuth
/// sectors, and their spread as a measure of the lattice's anisotropy) and height on the axis, and
/// the laws of Lube et al. (2004) they are compared with (docs/method/geometry-3d.md, "Measures").
///
/// Definitions (particle centres, as the 2D measures of deposit.h):
/// - The floor is the plane through `axis.point` normal to `axis.up`; a particle's height is its
///   distance above it, its radius its distance from the axis, its azimuth the angle in the floor
///   plane from `axis.azimuth_zero` towards `axis.azimuth_quarter`.
/// - The sectors split [0, span] (90° for a quarter domain, 180° half, 360° full) into equal
///   azimuth ranges, each [begin, end) (the last closed).
/// - A sector's runout is the farthest bottom-layer particle that is not splashed: the bottom layer
///   is the particles of height ≤ one spacing. A row of the deposit stands with its centres half a
///   spacing above the floor surface; beyond the deposit's edge a sparse sheet of particles that
///   have lost their neighbours rides higher, 1.0–1.7 spacings at rest (measured: the a = 2 column at
///   r0/Δp = 10–40), and reaches further as the spacing shrinks: the layer leaves it out, the few
///   of its particles below one spacing aside. Sorted by radius, the
///   farthest ones whose gap to the next particle inwards exceeds deposit_link_spacings (2)
///   spacings are dropped, as the 2D deposit drops particles farther than that from its body. A
///   sector without a bottom-layer particle has runout 0.
/// - runout_radius_m is the mean over the sectors, runout_radius_spread_m the largest minus the
///   smallest.
/// - runout_radius_thick_m (with a toe thickness t > 0, else NaN), as the 2D runout_thick_m
///   (deposit.h): per sector, the radius of the top particle of the outermost radial strip (width
///   one spacing) whose deposit is at least t thick, a strip's thickness being its top particle's
///   height + half a spacing (the top of its cell), the top being that of the strip's soil held up
///   from the floor, as for height_m below (a grain thrown into the air over a strip, or one
///   bouncing beyond the deposit, is no strip's top); the mean over the sectors. Unlike the runout
///   radius it ignores the edge thinner than t, a sheet one particle thick whose reach grows as the
///   spacing shrinks; t must span at least two spacings to be resolved.
/// - height_m is the top of the highest particle's cell, half a spacing above its centre, among the
///   particles within two spacings of the axis (a quarter domain's nearest particles lie √2/2
///   spacing from it on the lattice (i + ½)Δp) that the soil holds up: sorted by height, from the
///   lowest (which must lie within two spacings of the floor, else there is no soil on the axis and
///   the height is 0) up to the first gap of more than two spacings. The cell's top, not the
///   centre, so that a column whose cells fill 0 ≤ y ≤ H0 measures H0 before it moves: Lube et al.'s
///   H∞ = H0 for short columns is then met by an undisturbed top at any resolution.
#include <span>
#include <vector>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

struct DepositAxis {
  Vec3 point;            ///< on the axis, on the floor surface
  Vec3 up;               ///< unit, along the axis, against gravity
  Vec3 azimuth_zero;     ///< unit, in the floor plane: azimuth 0
  Vec3 azimuth_quarter;  ///< unit, in the floor plane: azimuth 90°
};

/// The bottom layer's depth above the floor surface, in spacings.
inline constexpr double bottom_layer_spacings = 1.0;

struct AxisymmetricDeposit {
  double runout_radius_m;         ///< mean over the sectors
  double runout_radius_spread_m;  ///< largest minus smallest over the sectors
  double runout_radius_thick_m;   ///< mean over the sectors; NaN without a toe thickness
  double height_m;                ///< on the axis
  std::vector<double> sector_runout_m;
};

/// The measures above over `sectors` sectors of [0, span_deg], runout_radius_thick_m at
/// `toe_thickness` (0: not measured); throws std::invalid_argument on no particle, a non-positive
/// spacing, span outside (0, 360] or fewer than one sector.
AxisymmetricDeposit measure_axisymmetric_deposit(std::span<const Vec3> soil, const DepositAxis& axis,
                                                 double spacing, double span_deg, int sectors,
                                                 double toe_thickness = 0.0);

/// Sectors of about 10° over a span: 9 for a quarter, 18 for a half, 36 for the full circle.
inline int default_sectors(double span_deg) {
  return span_deg <= 10.0 ? 1 : static_cast<int>(span_deg / 10.0 + 0.5);
}

/// The laws of axisymmetric collapses of dry granular columns, from the experiments of Lube,
/// Huppert, Sparks & Hallworth (2004), J. Fluid Mech. 508:175–199 (sands, salt, rice, couscous,
/// sugar; r0 = 1.7–9.7 cm), with a = H0/r0 the column's aspect ratio. Quoted as in Staron & Hinch
/// (2005, J. Fluid Mech. 545:1–27) and Szewc (2017, Granular Matter 19:3).
namespace lube2004 {
/// (r∞ − r0)/r0 = 1.24 a for a ≤ 1.7, 1.6 a^½ above.
double runout_ratio(double a);
/// H∞/r0: H∞ = H0 (the top undisturbed) for small a, 0.88 a^⅙ for tall columns. As quoted the two
/// branches switch at a ≈ 0.74, where 0.88 a^⅙ = 0.84 exceeds a = H0/r0 (a deposit higher than its
/// column); we take the smaller of the two, min(a, 0.88 a^⅙), which switches at a = 0.88^{6/5} ≈ 0.858.
double height_ratio(double a);
/// t∞ ≈ 3 (H0/g)^½ (s): the time the flow takes to stop.
double time_to_rest(double column_height, double gravity);
}  // namespace lube2004

}  // namespace soilsph::sph
