#pragma once
/// @file
/// Soil shapes of space as data: a shape answers `contains(p)` and `bounds()`, and the soil lattice
/// origin + (iΔp, jΔp, kΔp) is filled with the nodes a shape contains (docs/method/geometry-3d.md).
#include <cmath>
#include <concepts>
#include <vector>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// A solid of space: which points it holds, and a box that holds them all.
template <class S>
concept SolidShape = requires(const S& shape, Vec3 p) {
  { shape.contains(p) } -> std::convertible_to<bool>;
  { shape.bounds() } -> std::same_as<Box3>;
};

/// The lattice of soil nodes origin + (iΔp, jΔp, kΔp): the same in 3D as `[scene] lattice_origin` in 2D.
struct Lattice3 {
  Vec3 origin;
  double spacing;

  Vec3 node(long long i, long long j, long long k) const {
    return {origin.x + static_cast<double>(i) * spacing, origin.y + static_cast<double>(j) * spacing,
            origin.z + static_cast<double>(k) * spacing};
  }
  /// The smallest and largest index whose node lies in [lo, hi] along one axis; a bound on a node
  /// keeps it whatever the round-off (10⁻⁶ Δp, as the 2D lattice does).
  long long first_at_or_above(double lo, double o) const {
    return static_cast<long long>(std::ceil((lo - o) / spacing - 1e-6));
  }
  long long last_at_or_below(double hi, double o) const {
    return static_cast<long long>(std::floor((hi - o) / spacing + 1e-6));
  }
};

/// The lattice nodes the shape contains, within its bounds, ordered by k (z), then j (y), then i (x).
template <SolidShape Shape>
std::vector<Vec3> lattice_nodes_inside(const Shape& shape, const Lattice3& lattice) {
  const Box3 b = shape.bounds();
  const Vec3 o = lattice.origin;
  const long long i0 = lattice.first_at_or_above(b.lo.x, o.x), i1 = lattice.last_at_or_below(b.hi.x, o.x);
  const long long j0 = lattice.first_at_or_above(b.lo.y, o.y), j1 = lattice.last_at_or_below(b.hi.y, o.y);
  const long long k0 = lattice.first_at_or_above(b.lo.z, o.z), k1 = lattice.last_at_or_below(b.hi.z, o.z);
  std::vector<Vec3> nodes;
  for (long long k = k0; k <= k1; ++k)
    for (long long j = j0; j <= j1; ++j)
      for (long long i = i0; i <= i1; ++i)
        if (const Vec3 p = lattice.node(i, j, k); shape.contains(p)) nodes.push_back(p);
  return nodes;
}

}  // namespace soilsph::sph
