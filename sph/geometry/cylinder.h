#pragma once
/// @file
/// A vertical cylinder of soil, whole or cut to the half or quarter that a symmetric problem runs:
/// the axisymmetric column shorthand's soil and a 3D region's `shape = "cylinder"`.
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// Which part of a cylinder is kept; the rest is mirrored by free-slip symmetry planes through its axis.
enum class ColumnSymmetry {
  Quarter,  ///< "quarter": x ≥ x_c, z ≥ z_c (azimuth span 90°)
  Half,     ///< "half": z ≥ z_c (180°)
  None,     ///< "none" (a region's "whole"): the whole cylinder (360°)
};

/// A cylinder of soil: axis along y through its base centre (x_c, y_c, z_c), radius r0,
/// y_c ≤ y ≤ y_c + H0, cut to the part its symmetry keeps. A SolidShape (geometry/solid.h): its
/// nodes are the soil. The shorthand's base centre is the origin.
struct ColumnCylinder {
  double radius;  ///< r0 (m)
  double height;  ///< H0 (m)
  ColumnSymmetry symmetry;
  Vec3 base{};  ///< the centre of its base (m)

  /// With d = p − base: d.x² + d.z² ≤ r0² (relative round-off 10⁻⁹), 0 ≤ d.y ≤ H0 (10⁻⁹ H0), and
  /// d.x ≥ 0 (quarter), d.z ≥ 0 (quarter and half).
  bool contains(Vec3 p) const;
  Box3 bounds() const;
  /// The part's share of the whole cylinder: 1/4, 1/2 or 1.
  double share() const;
};

}  // namespace soilsph::sph
