#include "sph/geometry/read_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "constitutive/parameters.h"
#include "sph/geometry/polygon.h"
#include "sph/geometry/read_particles.h"

#include <filesystem>

namespace soilsph::sph {

namespace {

toml::array as_array(Vec2 v) { return toml::array{v.x, v.y}; }

}  // namespace

WallKindRead read_wall_kind(const TableReader& t, toml::table& resolved) {
  const std::string kind = t.choice("kind", {"free-slip", "no-slip", "frictional", "symmetry"});
  resolved.insert("kind", kind);
  if (kind == "symmetry") {
    // The plane of a symmetric problem's mirror image: what crosses it comes back from the other
    // half, so it holds no shear (free slip) and stays where the symmetry puts it.
    if (t.has("wall_friction_angle"))
      t.fail("wall_friction_angle",
             "is not taken with kind = \"symmetry\": a symmetry plane mirrors the soil without friction "
             "(free slip); a rough wall is kind = \"frictional\"");
    for (const std::string_view key : {"velocity", "start", "end", "removed_at"})
      if (t.has(key))
        t.fail(key,
               "is not taken with kind = \"symmetry\": a symmetry plane stays where the symmetry puts it "
               "(a wall that moves or goes is kind = \"free-slip\")");
    return {.kind = WallKind::FreeSlip, .friction_angle = 0.0, .symmetry_plane = true};
  }
  const WallKind k = kind == "free-slip" ? WallKind::FreeSlip : kind == "no-slip" ? WallKind::NoSlip : WallKind::Frictional;
  double friction_angle = 0.0;
  if (k == WallKind::Frictional) {
    friction_angle = t.number("wall_friction_angle", Range::open(0.0, 90.0), "degrees");
    resolved.insert("wall_friction_angle", friction_angle);
  }
  return {.kind = k, .friction_angle = friction_angle, .symmetry_plane = false};
}

std::vector<std::pair<const toml::table*, std::string>> tables_of(const toml::table& root, const std::string& source,
                                                                  std::string_view name) {
  std::vector<std::pair<const toml::table*, std::string>> tables;
  const toml::node* node = root.get(name);
  if (!node) return tables;
  const toml::array* array = node->as_array();
  if (!array) throw ParameterError(source + ": " + std::string(name) + " must be an array of tables ([[" + std::string(name) + "]])");
  for (std::size_t k = 0; k < array->size(); ++k) {
    const std::string label = std::string(name) + " #" + std::to_string(k + 1);
    if (!(*array)[k].is_table()) throw ParameterError(source + ": [" + label + "] must be a table ([[" + std::string(name) + "]])");
    tables.emplace_back((*array)[k].as_table(), label);
  }
  return tables;
}

template <int dim>
Vec<dim> read_vector_of(const toml::node& node, const std::string& where, std::string_view unit) {
  const toml::array* a = node.as_array();
  const std::string expected = std::string(dim == 2 ? " must be [x, y], two" : " must be [x, y, z], three") +
                               " finite numbers (" + std::string(unit) + ", |value| <= " +
                               format_number(kLargestCoordinate) + ")";
  if (!a || a->size() != dim) throw ParameterError(where + expected);
  double c[dim];
  for (int k = 0; k < dim; ++k) {
    const toml::node& e = (*a)[static_cast<std::size_t>(k)];
    const std::optional<double> x = e.value<double>();
    if (!x || e.is_boolean() || !std::isfinite(*x) || std::abs(*x) > kLargestCoordinate) throw ParameterError(where + expected);
    c[k] = *x;
  }
  if constexpr (dim == 2)
    return {c[0], c[1]};
  else
    return {c[0], c[1], c[2]};
}
template Vec2 read_vector_of<2>(const toml::node&, const std::string&, std::string_view);
template Vec3 read_vector_of<3>(const toml::node&, const std::string&, std::string_view);

std::vector<Vec2> points_of(const toml::table& table, const std::string& where, std::size_t least) {
  const toml::node* node = table.get("points");
  const std::string hint = " (an array of at least " + std::to_string(least) + " [x, y] points, m)";
  if (!node) throw ParameterError(where + " points is missing" + hint);
  const toml::array* a = node->as_array();
  if (!a || a->size() < least) throw ParameterError(where + " points must be" + hint);
  std::vector<Vec2> points;
  for (std::size_t k = 0; k < a->size(); ++k)
    points.push_back(read_vector((*a)[k], where + " points[" + std::to_string(k + 1) + "]", "m"));
  return points;
}

namespace {
toml::array array_of(const std::vector<Vec2>& points) {
  toml::array a;
  for (const Vec2& p : points) a.push_back(as_array(p));
  return a;
}
}  // namespace

void check_on_cell_edge(const std::string& where, std::string_view key, char axis, double value, double origin,
                        double dx) {
  const double cells = (value - origin) / dx - 0.5, nearest = std::round(cells);
  if (std::abs(cells - nearest) <= 1e-6) return;
  const double below = origin + (std::floor(cells) + 0.5) * dx, above = below + dx;
  throw ParameterError(where + " " + std::string(key) + " " + axis + " = " + format_number(value) +
                       " m does not fall on a cell edge of the lattice (" + axis + " = " +
                       format_number(origin) +
                       " + (i + 1/2) x [scene] particle_spacing = " + format_number(dx) +
                       " m); the nearest are " + format_number(below) + " and " + format_number(above) +
                       " m (or move [scene] lattice_origin, or take another particle_spacing)");
}

namespace {

/// A `shape = "particles"` entry: its `file` (relative to the scene file's folder; recorded as an
/// absolute path, so that a checkpoint's scene finds it), one region per material it names.
std::vector<Region> read_particles_region(const TableReader& t, const toml::table& table, const std::string& label,
                                          const std::string& source, double dx,
                                          const std::vector<std::string>& materials, toml::table& resolved) {
  if (t.has("material")) t.fail("material", "is given by the particle file's region column (shape = \"particles\")");
  t.accept({"file"});
  const toml::node* node = table.get("file");
  if (!node || !node->is_string()) t.fail("file", "must be given as a string: the CSV file of the particles (x,y,region)");
  const std::string name = **node->as_string();
  std::filesystem::path file(name);
  if (file.is_relative()) file = std::filesystem::path(source).parent_path() / file;
  file = std::filesystem::absolute(file).lexically_normal();
  resolved.insert("file", file.string());
  t.reject_unknown_keys();
  return read_particle_file(file.string(), "[" + label + "]", dx, source, materials);
}

std::vector<Region> read_region(const toml::table& table, const std::string& label, const std::string& source, double dx,
                   Vec2 origin, const std::vector<std::string>& materials, toml::table& resolved) {
  const TableReader t(table, source, label);
  const std::string where = source + ": [" + label + "]";
  Region region;
  region.name = "[" + label + "]";
  const std::string shape = t.choice("shape", {"box", "polygon", "particles"});
  resolved.insert("shape", shape);
  if (shape == "particles") return read_particles_region(t, table, label, source, dx, materials, resolved);
  if (shape == "box") {
    region.shape = Region::Shape::Box;
    t.accept({"min", "max"});
    const toml::node* lo = table.get("min");
    const toml::node* hi = table.get("max");
    if (!lo || !hi) throw ParameterError(where + " a box needs min = [x, y] and max = [x, y] (m)");
    const Vec2 a = read_vector(*lo, where + " min", "m"), b = read_vector(*hi, where + " max", "m");
    if (!(b.x > a.x && b.y > a.y))
      throw ParameterError(where + " max must exceed min in x and in y (an empty box)");
    check_on_cell_edge(where, "min", 'x', a.x, origin.x, dx);
    check_on_cell_edge(where, "min", 'y', a.y, origin.y, dx);
    check_on_cell_edge(where, "max", 'x', b.x, origin.x, dx);
    check_on_cell_edge(where, "max", 'y', b.y, origin.y, dx);
    region.outline = {a, {b.x, a.y}, b, {a.x, b.y}};
    resolved.insert("min", as_array(a));
    resolved.insert("max", as_array(b));
  } else {
    region.shape = Region::Shape::Polygon;
    t.accept({"points"});
    region.outline = points_of(table, where, 3);
    if (const auto defect = polygon_defect(region.outline)) throw ParameterError(where + " points: the polygon " + *defect);
    resolved.insert("points", array_of(region.outline));
    if (signed_area(region.outline) < 0.0) std::reverse(region.outline.begin(), region.outline.end());
  }
  if (materials.size() == 1 && !t.has("material")) {
    region.material = materials.front();
  } else {
    std::vector<std::string_view> names(materials.begin(), materials.end());
    region.material = t.choice("material", names);
  }
  if (!region.material.empty()) resolved.insert("material", region.material);
  t.reject_unknown_keys();
  return {region};
}

/// A symmetry line mirrors the soil across one line, x = const or y = const (its ghosts are the
/// soil's images, reflected along one axis: stages/mirror_images.h): its points must lie on it.
void check_symmetry_line(const TableReader& t, const std::vector<Vec2>& points) {
  const Vec2 first = points.front(), along = points.back() - first;
  for (std::size_t k = 1; k + 1 < points.size(); ++k) {
    const Vec2 d = points[k] - first;
    if (std::abs(cross(d, along)) > 1e-9 * norm(d) * norm(along))
      t.fail("points", "point " + std::to_string(k + 1) +
                           " is off the line through the first and the last: a symmetry line (kind = "
                           "\"symmetry\") is straight (a bent wall is kind = \"free-slip\")");
  }
  if (std::min(std::abs(along.x), std::abs(along.y)) > 1e-12 * norm(along))
    t.fail("points",
           "run along x or y for kind = \"symmetry\" (the soil's images are reflected along one "
           "axis); this line is oblique: take kind = \"free-slip\"");
}

Wall read_wall(const toml::table& table, const std::string& label, const std::string& source, toml::table& resolved) {
  const TableReader t(table, source, label);
  const std::string where = source + ": [" + label + "]";
  Wall wall;
  wall.name = "[" + label + "]";
  if (t.has("name")) wall.label = t.word("name");
  t.accept({"points", "velocity"});
  wall.points = points_of(table, where, 2);
  for (std::size_t k = 0; k + 1 < wall.points.size(); ++k) {
    const double length = norm(wall.points[k + 1] - wall.points[k]);
    if (!(length > 1e-9)) throw ParameterError(where + " points: piece " + std::to_string(k + 1) + " has zero length");
    if (k > 0) {
      const Vec2 u = wall.points[k] - wall.points[k - 1], v = wall.points[k + 1] - wall.points[k];
      if (std::abs(cross(u, v)) <= 1e-12 * norm(u) * norm(v) && dot(u, v) < 0.0)
        throw ParameterError(where + " points: the polyline folds back on itself at point " + std::to_string(k + 1));
    }
  }
  resolved.insert("points", array_of(wall.points));
  const WallKindRead kind = read_wall_kind(t, resolved);
  wall.kind = kind.kind, wall.friction_angle = kind.friction_angle, wall.symmetry_plane = kind.symmetry_plane;
  if (wall.symmetry_plane) check_symmetry_line(t, wall.points);
  if (t.has("removed_at")) {
    wall.motion.removed_at = t.number("removed_at", Range::non_negative(), "s");
    resolved.insert("removed_at", wall.motion.removed_at);
  }
  if (const toml::node* v = table.get("velocity")) {
    wall.motion.velocity = read_vector(*v, where + " velocity", "m/s");
    wall.motion.start = t.number_or("start", 0.0, Range::non_negative(), "s");
    wall.motion.end = t.number("end", Range::open(wall.motion.start, std::numeric_limits<double>::infinity()), "s");
    resolved.insert("velocity", as_array(wall.motion.velocity));
    resolved.insert("start", wall.motion.start);
    resolved.insert("end", wall.motion.end);
  } else if (t.has("start") || t.has("end")) {
    t.fail(t.has("start") ? "start" : "end", "needs velocity = [vx, vy] (m/s): start and end time a motion");
  }
  t.reject_unknown_keys();
  return wall;
}

}  // namespace

toml::array read_boundaries(const toml::table& root, const std::string& source, std::vector<Wall>& walls) {
  toml::array resolved;
  int k = 0;
  for (const auto& [table, label] : tables_of(root, source, "boundaries")) {
    toml::table r;
    Wall wall = read_wall(*table, label, source, r);
    if (wall.label.empty()) wall.label = "boundary_" + std::to_string(++k);
    else ++k;
    for (const Wall& other : walls)
      if (other.label == wall.label)
        throw ParameterError(source + ": " + wall.name + " name = \"" + wall.label + "\" is also the name of " +
                             other.name + " (boundary names must differ: they label boundary_forces.csv)");
    r.insert("name", wall.label);
    walls.push_back(std::move(wall));
    resolved.push_back(std::move(r));
  }
  return resolved;
}

ReadLayout read_layout(const toml::table& root, const std::string& source, double spacing, Vec2 origin,
                       const std::vector<std::string>& materials) {
  ReadLayout out;
  out.layout.lattice_origin = origin;
  for (const auto& [table, label] : tables_of(root, source, "regions")) {
    toml::table r;
    for (Region& region : read_region(*table, label, source, spacing, origin, materials, r))
      out.layout.regions.push_back(std::move(region));
    out.regions.push_back(std::move(r));
  }
  if (out.layout.regions.empty()) throw ParameterError(source + ": no soil: give [[regions]] or the [scene] column keys");
  out.boundaries = read_boundaries(root, source, out.layout.walls);
  return out;
}

}  // namespace soilsph::sph
