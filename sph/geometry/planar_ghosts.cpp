#include "sph/geometry/planar_ghosts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "sph/geometry/polygon.h"

namespace soilsph::sph {

namespace {
double extent_of(const PlanarWall& w) {
  double extent = 0.0;
  for (const Vec2& q : w.outline) extent = std::max(extent, norm(q));
  return std::max(extent, 1e-300);
}

/// The edge a → b of `wall` lies in `other` and `other` holds the soil back towards `wall`.
bool meets_at_inner_corner(const PlanarWall& wall, Vec2 a, Vec2 b, const PlanarWall& other) {
  const double tolerance = 1e-9 * std::max(extent_of(wall), extent_of(other));
  for (const Vec3 p : {wall.at(a), wall.at(b)})
    if (std::abs(other.height_above(p)) > tolerance ||
        !inside_or_on(other.outline, other.in_plane(p), tolerance))
      return false;
  const Vec2 d = b - a, outward_2d = (1.0 / norm(d)) * Vec2{d.y, -d.x};  // the soil's outline is on the left
  const Vec3 outward = outward_2d.x * wall.u + outward_2d.y * wall.v;
  return dot(other.inward, outward) < -1e-9;
}
}  // namespace

std::vector<Vec2> grown_outline(std::span<const PlanarWall> walls, std::size_t w, double reach) {
  const PlanarWall& wall = walls[w];
  const std::vector<Vec2>& o = wall.outline;
  const std::size_t n = o.size();
  // Each edge k as the line {q : q·normal_k = offset_k}, normal_k its outward unit normal.
  std::vector<Vec2> normal(n);
  std::vector<double> offset(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = o[k], b = o[(k + 1) % n], d = b - a;
    normal[k] = (1.0 / norm(d)) * Vec2{d.y, -d.x};
    bool grows = false;
    for (std::size_t other = 0; other < walls.size() && !grows; ++other)
      grows = other != w && meets_at_inner_corner(wall, a, b, walls[other]);
    offset[k] = dot(a, normal[k]) + (grows ? reach : 0.0);
  }
  std::vector<Vec2> grown(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t before = (k + n - 1) % n;
    const Vec2 n1 = normal[before], n2 = normal[k];
    const double det = cross(n1, n2);
    if (std::abs(det) <= 1e-12) {  // collinear edges: move the vertex with its edge
      grown[k] = o[k] + (offset[k] - dot(o[k], n2)) * n2;
      continue;
    }
    // Cramer's rule for q·n1 = offset_before, q·n2 = offset_k.
    grown[k] = {(offset[before] * n2.y - offset[k] * n1.y) / det,
                (n1.x * offset[k] - n2.x * offset[before]) / det};
  }
  return grown;
}

std::vector<GhostPoint3> planar_ghost_points(std::span<const PlanarWall> walls, const Lattice3& lattice,
                                             int layers, const std::vector<bool>& mirrored) {
  const double dx = lattice.spacing, depth = layers * dx, tolerance = 1e-9 * dx;
  std::vector<GhostPoint3> ghosts;
  std::set<std::array<long long, 3>> taken;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    if (!mirrored.empty() && mirrored[w]) continue;
    const PlanarWall& wall = walls[w];
    const std::vector<Vec2> outline = grown_outline(walls, w, depth);
    // The box of the slab behind the grown outline.
    Box3 box{wall.at(outline[0]), wall.at(outline[0])};
    for (const Vec2& q : outline) {
      const Vec3 p = wall.at(q);
      box = merged(box, Box3{p, p});
      box = merged(box, Box3{p - depth * wall.inward, p - depth * wall.inward});
    }
    const Vec3 o = lattice.origin;
    const long long i0 = lattice.first_at_or_above(box.lo.x, o.x),
                    i1 = lattice.last_at_or_below(box.hi.x, o.x);
    const long long j0 = lattice.first_at_or_above(box.lo.y, o.y),
                    j1 = lattice.last_at_or_below(box.hi.y, o.y);
    const long long k0 = lattice.first_at_or_above(box.lo.z, o.z),
                    k1 = lattice.last_at_or_below(box.hi.z, o.z);
    for (long long k = k0; k <= k1; ++k)
      for (long long j = j0; j <= j1; ++j)
        for (long long i = i0; i <= i1; ++i) {
          const Vec3 p = lattice.node(i, j, k);
          const double behind = -wall.height_above(p);
          if (behind <= tolerance || behind > depth + tolerance) continue;
          if (!inside_or_on(outline, wall.in_plane(p), tolerance)) continue;
          if (!taken.insert({i, j, k}).second) continue;
          ghosts.push_back({p, wall.inward, static_cast<int>(w)});
        }
  }
  return ghosts;
}

}  // namespace soilsph::sph
