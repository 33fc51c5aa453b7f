#include "sph/geometry/lattice.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <utility>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"

namespace soilsph::sph {

std::vector<SoilNode> soil_nodes(const Layout& layout, double dx, const std::string& source) {
  std::vector<SoilNode> nodes;
  std::set<std::pair<long long, long long>> taken;  // (i, j) of earlier regions (overlaps only)
  const Vec2 o = layout.lattice_origin;
  for (std::size_t r = 0; r < layout.regions.size(); ++r) {
    const Region& region = layout.regions[r];
    if (region.shape == Region::Shape::Particles) {  // as read (geometry/read_particles.h), off the lattice too
      for (const Vec2& p : region.particles) nodes.push_back({p, static_cast<int>(r)});
      continue;
    }
    Vec2 lo = region.outline.front(), hi = lo;
    for (const Vec2& v : region.outline) lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    // Index ranges with a tolerance, so that a box side on a node keeps it whatever the round-off.
    const auto i0 = static_cast<long long>(std::ceil((lo.x - o.x) / dx - 1e-6));
    const auto i1 = static_cast<long long>(std::floor((hi.x - o.x) / dx + 1e-6));
    const auto j0 = static_cast<long long>(std::ceil((lo.y - o.y) / dx - 1e-6));
    const auto j1 = static_cast<long long>(std::floor((hi.y - o.y) / dx + 1e-6));
    const std::size_t before = nodes.size();
    for (long long j = j0; j <= j1; ++j)
      for (long long i = i0; i <= i1; ++i) {
        // o + i Δp: with the column's origin (0, 0) exactly the column's i Δp.
        const Vec2 p{o.x + static_cast<double>(i) * dx, o.y + static_cast<double>(j) * dx};
        if (region.shape == Region::Shape::Polygon && !inside_or_on(region.outline, p, 1e-9 * dx)) continue;
        if (layout.regions.size() > 1 && !taken.insert({i, j}).second) continue;
        nodes.push_back({p, static_cast<int>(r)});
      }
    if (nodes.size() == before)
      throw ParameterError(source + ": " + region.name + " holds no particle of the lattice at particle_spacing = " +
                           format_number(dx) + " m (smaller than a spacing, or covered by earlier regions)");
  }
  return nodes;
}

namespace {
/// The direction of the piece that follows the wall's last point: the first piece of another wall
/// that starts there (two walls of different kinds meeting at a corner), or none.
std::optional<Vec2> continuation(const Layout& layout, const Wall& wall, double dx) {
  const Vec2 end = wall.points.back();
  for (const Wall& other : layout.walls)
    if (&other != &wall && other.motion.removed_at > 0.0 && norm(other.points.front() - end) <= 1e-9 * dx)
      return other.points[1] - other.points[0];
  return std::nullopt;
}

/// The strip of the piece that ends at the wall's first point, in another wall that has ghosts, or
/// none.
std::optional<GhostStrip> predecessor(const Layout& layout, const Wall& wall, double dx, int layers) {
  const Vec2 start = wall.points.front();
  for (const Wall& other : layout.walls)
    if (&other != &wall && other.motion.removed_at > 0.0 && !other.symmetry_plane &&
        norm(other.points.back() - start) <= 1e-9 * dx)
      return strips_of(layout, other, dx, layers).back();
  return std::nullopt;
}

/// The direction of the symmetry line that ends at the wall's first point, or none. The line has no
/// ghosts (the soil's mirror images stand behind it, stages/mirror_images.h), so where the wall
/// turns from it towards the soil the wall's first piece fills the corner block behind both, as
/// the piece before an inner corner does otherwise: the floor's ghosts reach on under the line.
std::optional<Vec2> symmetry_line_before(const Layout& layout, const Wall& wall, double dx) {
  const Vec2 start = wall.points.front();
  for (const Wall& other : layout.walls)
    if (&other != &wall && other.symmetry_plane && norm(other.points.back() - start) <= 1e-9 * dx)
      return other.points.back() - other.points[other.points.size() - 2];
  return std::nullopt;
}
}  // namespace

std::vector<GhostStrip> strips_of(const Layout& layout, const Wall& wall, double dx, int layers) {
  if (!wall.strips.empty()) return wall.strips;
  std::vector<GhostStrip> strips;
  const std::size_t pieces = wall.points.size() - 1;
  for (std::size_t s = 0; s < pieces; ++s) {
    const Vec2 a = wall.points[s], b = wall.points[s + 1];
    const double length = norm(b - a);
    const Vec2 t = (1.0 / length) * (b - a), out{t.y, -t.x};  // the soil is on the left
    GhostStrip strip{a + (0.5 * dx) * t - (0.5 * dx) * out, t, out,
                     std::max(1, static_cast<int>(std::lround(length / dx)))};
    const std::optional<Vec2> next = s + 1 < pieces ? std::optional<Vec2>(wall.points[s + 2] - b)
                                                    : continuation(layout, wall, dx);
    if (next && cross(t, *next) > 1e-9 * norm(*next)) strip.count += layers;  // inner corner: fill its block
    if (s == 0)
      if (const std::optional<Vec2> line = symmetry_line_before(layout, wall, dx);
          line && cross(*line, t) > 1e-9 * norm(*line))
        strip.anchor = strip.anchor - (layers * dx) * t, strip.count += layers;
    strips.push_back(strip);
  }
  return strips;
}

std::vector<GhostPoint> ghost_points(const Layout& layout, double dx, int layers) {
  std::vector<GhostPoint> points;
  for (std::size_t w = 0; w < layout.walls.size(); ++w) {
    const Wall& wall = layout.walls[w];
    // Withdrawn at t = 0: never there. A symmetry line: the soil's mirror images stand behind it.
    if (wall.motion.removed_at <= 0.0 || wall.symmetry_plane) continue;
    const std::vector<GhostStrip> strips = strips_of(layout, wall, dx, layers);
    const std::optional<GhostStrip> before = wall.strips.empty() ? predecessor(layout, wall, dx, layers) : std::nullopt;
    for (std::size_t s = 0; s < strips.size(); ++s) {
      const GhostStrip& g = strips[s];
      // After an outer corner, the previous strip's rows already cover the wedge behind it.
      const GhostStrip* previous = s > 0 ? &strips[s - 1] : before ? &*before : nullptr;
      if (!wall.strips.empty() || !previous || !(cross(previous->tangent, g.tangent) < 0.0)) previous = nullptr;
      const Vec2 corner = wall.points[std::min(s, wall.points.size() - 1)];
      for (int k = 1; k <= layers; ++k)
        for (int c = 0; c < g.count; ++c) {
          // Left to right as written: anchor + (cΔp) t + (kΔp) n, the column's own operations.
          const Vec2 along = (c * dx) * g.tangent, behind = (k * dx) * g.outward;
          const Vec2 p{g.anchor.x + along.x + behind.x, g.anchor.y + along.y + behind.y};
          if (previous && dot(p - corner, previous->tangent) < 0.0 &&
              dot(p - corner, previous->outward) < (layers + 0.5) * dx)
            continue;
          points.push_back({p, {-g.outward.x, -g.outward.y}, static_cast<int>(w)});
        }
    }
  }
  return points;
}

}  // namespace soilsph::sph
