#include "sph/read_boundaries_3d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "constitutive/parameters.h"
#include "sph/geometry/read_layout.h"

namespace soilsph::sph {

namespace {

toml::array as_array(Vec3 v) {
  return toml::array{v.x, v.y, v.z};
}

/// "FILE: [boundaries #K] key", where an error about `key` of `t`'s table points.
std::string where(const TableReader& t, std::string_view key) {
  return t.source() + ": [" + t.table_name() + "] " + std::string(key);
}

/// `shape = "rectangle"`: corner, corner + a, corner + a + b, corner + b for edges = [a, b], the
/// soil on the side of a × b (geometry/planar_wall.h, rectangle_wall).
PlanarWall read_rectangle(const TableReader& t, const toml::table& table, toml::table& resolved) {
  t.accept({"corner", "edges"});
  const std::string hint =
      " (a rectangle is corner = [x, y, z] and edges = [[ax, ay, az], [bx, by, bz]], its two perpendicular "
      "edges "
      "from the corner, m; the soil on the side of a x b)";
  const toml::node* corner_node = table.get("corner");
  if (!corner_node) t.fail("corner", "is missing" + hint);
  const Vec3 corner = read_vector_of<3>(*corner_node, where(t, "corner"), "m");
  const toml::node* edges_node = table.get("edges");
  if (!edges_node) t.fail("edges", "is missing" + hint);
  const toml::array* edges = edges_node->as_array();
  if (!edges || edges->size() != 2) t.fail("edges", "must be two edges" + hint);
  const Vec3 a = read_vector_of<3>((*edges)[0], where(t, "edges") + "[1]", "m"),
             b = read_vector_of<3>((*edges)[1], where(t, "edges") + "[2]", "m");
  if (!(norm(a) > 1e-9) || !(norm(b) > 1e-9))
    t.fail("edges", "has an edge of zero length (allowed: edges longer than 1e-9 m)");
  const double cosine = dot(a, b) / (norm(a) * norm(b));
  if (std::abs(cosine) > 1e-9)
    t.fail("edges",
           "are at " + format_number(std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi) +
               " degrees to each other: a rectangle's edges are perpendicular (another quadrilateral is "
               "shape = \"polygon\")");
  resolved.insert("corner", as_array(corner));
  resolved.insert("edges", toml::array{as_array(a), as_array(b)});
  return rectangle_wall(corner, a, b, where(t, "corner"));
}

/// `shape = "polygon"`: at least 3 coplanar points of a simple polygon; the soil on the side the
/// right-hand rule gives (counter-clockwise seen from the soil), or of `normal` if given.
PlanarWall read_polygon(const TableReader& t, const toml::table& table, toml::table& resolved) {
  t.accept({"points", "normal"});
  const std::string hint = " (an array of at least 3 [x, y, z] points of one plane, m)";
  const toml::node* node = table.get("points");
  if (!node) t.fail("points", "is missing" + hint);
  const toml::array* a = node->as_array();
  if (!a || a->size() < 3) t.fail("points", "must be" + hint);
  std::vector<Vec3> points;
  toml::array points_resolved;
  for (std::size_t k = 0; k < a->size(); ++k) {
    points.push_back(read_vector_of<3>((*a)[k], where(t, "points") + "[" + std::to_string(k + 1) + "]", "m"));
    points_resolved.push_back(as_array(points.back()));
  }
  resolved.insert("points", std::move(points_resolved));
  PlanarWall wall = make_planar_wall(points, where(t, "points"));
  if (const toml::node* n = table.get("normal")) {
    const Vec3 normal = read_vector_of<3>(*n, where(t, "normal"), "a direction");
    if (!(norm(normal) > 0.0))
      t.fail("normal", "is zero (allowed: a vector normal to the polygon, towards the soil)");
    const double cosine = dot(normal, wall.inward) / norm(normal);
    if (std::abs(cosine) < 1.0 - 1e-9)
      t.fail("normal",
             "is " + format_number(std::acos(std::min(std::abs(cosine), 1.0)) * 180.0 / std::numbers::pi) +
                 " degrees off the polygon's normal (allowed: along it, to either side)");
    resolved.insert("normal", as_array(normal));
    if (cosine < 0.0) {  // the soil on the other side: walk the outline the other way round
      std::reverse(points.begin(), points.end());
      wall = make_planar_wall(points, where(t, "points"));
    }
  }
  return wall;
}

/// removed_at, and velocity from start to end, as a 2D wall's.
WallMotionOf<3> read_motion(const TableReader& t, const toml::table& table, toml::table& resolved) {
  WallMotionOf<3> motion;
  if (t.has("removed_at")) {
    motion.removed_at = t.number("removed_at", Range::non_negative(), "s");
    resolved.insert("removed_at", motion.removed_at);
  }
  t.accept({"velocity"});
  if (const toml::node* v = table.get("velocity")) {
    motion.velocity = read_vector_of<3>(*v, where(t, "velocity"), "m/s");
    motion.start = t.number_or("start", 0.0, Range::non_negative(), "s");
    motion.end = t.number("end", Range::open(motion.start, std::numeric_limits<double>::infinity()), "s");
    resolved.insert("velocity", as_array(motion.velocity));
    resolved.insert("start", motion.start);
    resolved.insert("end", motion.end);
  } else if (t.has("start") || t.has("end")) {
    t.fail(t.has("start") ? "start" : "end",
           "needs velocity = [vx, vy, vz] (m/s): start and end time a motion");
  }
  return motion;
}

}  // namespace

toml::array read_boundaries_3d(const toml::table& root, const std::string& source, std::vector<Wall3>& walls,
                               std::vector<Wall3>& withdrawn) {
  toml::array resolved;
  std::vector<std::string> names;
  for (const Wall3& w : walls) names.push_back(w.label);
  int k = 0;
  for (const auto& [table, label] : tables_of(root, source, "boundaries")) {
    ++k;
    const TableReader t(*table, source, label);
    toml::table r;
    const std::string shape = t.choice("shape", {"rectangle", "polygon"});
    r.insert("shape", shape);
    Wall3 wall;
    wall.plane = shape == "rectangle" ? read_rectangle(t, *table, r) : read_polygon(t, *table, r);
    const WallKindRead kind = read_wall_kind(t, r);
    wall.kind = kind.kind, wall.friction_angle = kind.friction_angle, wall.symmetry_plane = kind.symmetry_plane;
    if (wall.symmetry_plane && axis_along(wall.plane.inward) < 0)
      t.fail("kind", "= \"symmetry\" needs a plane normal to x, y or z (its ghosts are the soil's images, "
                     "reflected along one axis); this one's normal is not: take kind = \"free-slip\"");
    wall.motion = read_motion(t, *table, r);
    wall.label = t.has("name") ? t.word("name") : "boundary_" + std::to_string(k);
    if (std::find(names.begin(), names.end(), wall.label) != names.end())
      t.fail("name",
             "= \"" + wall.label +
                 "\" is already the name of another wall (wall names must differ: they label "
                 "boundary_forces.csv; the shorthands' are floor, fixed_wall, removable_wall, symmetry_x, "
                 "symmetry_z and symmetry_far)");
    names.push_back(wall.label);
    r.insert("name", wall.label);
    t.reject_unknown_keys();
    // Removed at 0: not there in the run, only in a gravity loading before it.
    (wall.motion.removed_at > 0.0 ? walls : withdrawn).push_back(std::move(wall));
    resolved.push_back(std::move(r));
  }
  return resolved;
}

Box3 domain_around_walls(Box3 domain, std::span<const Wall3> walls, double margin) {
  const Vec3 grow{margin, margin, margin};
  for (const Wall3& w : walls)
    for (const Vec2& q : w.plane.outline)
      for (const Vec3 p : {w.plane.at(q), w.plane.at(q) + w.motion.displacement(w.motion.end)})
        domain = merged(domain, Box3{p - grow, p + grow});
  return domain;
}

}  // namespace soilsph::sph
