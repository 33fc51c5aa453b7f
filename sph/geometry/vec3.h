#pragma once
/// @file
/// A point or vector of space (m, m/s, m/s²) and an axis-aligned box: what 3D geometry speaks.
/// `Vec<D>` names the vector of a dimension, so code written once for 2 and 3 dimensions says
/// `Vec<dim>` and uses the free functions below, which exist for both.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "sph/geometry/vec2.h"

namespace soilsph::sph {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::hypot(a.x, a.y, a.z); }
/// The component of a along an axis (0: x, 1: y, 2: z).
inline double component(Vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
/// a with its component along an axis replaced by v.
inline Vec3 with_component(Vec3 a, int axis, double v) {
  return {axis == 0 ? v : a.x, axis == 1 ? v : a.y, axis == 2 ? v : a.z};
}

/// The vector of a dimension: Vec<2> is Vec2, Vec<3> is Vec3.
template <int D>
  requires(D == 2 || D == 3)
using Vec = std::conditional_t<D == 2, Vec2, Vec3>;

/// An axis-aligned box [lo, hi] (a shape's bounds, a domain).
struct Box3 {
  Vec3 lo, hi;
  bool contains(Vec3 p) const {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
  /// The smallest box holding both.
  friend Box3 merged(const Box3& a, const Box3& b) {
    return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)},
            {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)}};
  }
};

}  // namespace soilsph::sph
