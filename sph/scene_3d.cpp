#include "sph/scene_3d.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sph/initial_state_3d.h"
#include "sph/read_boundaries_3d.h"
#include "sph/read_measures.h"
#include "sph/read_regions_3d.h"
#include "sph/scene_sections.h"

namespace soilsph::sph {

using namespace scene_sections;

double default_floor_radius(double column_radius, double column_height, double spacing) {
  // Twice Lube's runout beyond the column: SPH deposits of frictional soil run out farther than
  // the experiments' at coarse spacings, and a particle past the floor's edge falls off it.
  return column_radius * (1.0 + 2.0 * lube2004::runout_ratio(column_height / column_radius)) + 4.0 * spacing;
}

namespace {

constexpr Vec3 kUp{0.0, 1.0, 0.0};

/// length / spacing is a whole number (within 10⁻⁶ of it), as the 2D column checks its sides.
bool whole_spacings(double length, double spacing) {
  const double n = length / spacing;
  return n >= 1.0 - 1e-6 && std::abs(n - std::round(n)) <= 1e-6 * n;
}

void require_whole_spacings(const TableReader& t, std::string_view key, double length, double spacing) {
  if (whole_spacings(length, spacing)) return;
  std::ostringstream msg;
  msg << "= " << length << " m is " << length / spacing << " particle spacings (" << spacing
      << " m): the lattice fills it only with a whole number of them (allowed: a positive multiple of "
         "particle_spacing)";
  t.fail(key, msg.str());
}

/// [scene] gravity: a number g, (0, −g, 0), default 9.81; or [gx, gy, gz]. The shorthands stand on
/// a level floor, so gravity must point down y (or be zero). `extra` gets an array as read.
Vec3 read_gravity(const TableReader& t, const toml::table& table, toml::table& extra) {
  const toml::node* node = table.get("gravity");
  if (!node || !node->is_array())
    return {0.0, -t.number_or("gravity", 9.81, Range::closed(0.0, 1e4), "m/s^2"), 0.0};
  t.accept({"gravity"});
  const toml::array& a = *node->as_array();
  const std::string expected =
      "must be a number g (for [0, -g, 0]) or [gx, gy, gz], three finite numbers (m/s^2)";
  if (a.size() != 3) t.fail("gravity", expected);
  double c[3];
  for (std::size_t k = 0; k < 3; ++k) {
    const std::optional<double> v = a[k].value<double>();
    if (!v || a[k].is_boolean() || !std::isfinite(*v)) t.fail("gravity", expected);
    c[k] = *v;
  }
  const Vec3 g{c[0], c[1], c[2]};
  if (norm(g) > 1e4)
    t.fail("gravity", "has magnitude " + format_number(norm(g)) + " (allowed: <= 10000 m/s^2)");
  if (g.x != 0.0 || g.z != 0.0 || g.y > 0.0)
    t.fail("gravity", "must point down y, [0, -g, 0]: a 3D scene's column stands on a level floor y = const");
  extra.insert("gravity", toml::array{g.x, g.y, g.z});
  return g;
}

/// A rectangle wall of the shorthands (geometry/planar_wall.h: the soil on the side of a × b).
Wall3 wall(Vec3 corner, Vec3 a, Vec3 b, WallKind kind, const std::string& label, const std::string& source) {
  return {.plane = rectangle_wall(corner, a, b, source + ": the " + label),
          .kind = kind,
          .friction_angle = 0.0,
          .symmetry_plane = false,
          .label = label,
          .motion = {}};
}

/// A symmetry plane of the shorthands: a free-slip rectangle mirrored by the soil's images.
Wall3 symmetry_plane(Vec3 corner, Vec3 a, Vec3 b, const std::string& label, const std::string& source) {
  Wall3 plane = wall(corner, a, b, WallKind::FreeSlip, label, source);
  plane.symmetry_plane = true;
  return plane;
}

}  // namespace

/// The box of the floor's extent [x_lo, x_hi] × [z_lo, z_hi] grown by the ghost layers and the
/// kernel support, from below the floor's ghosts up to twice the soil's height above the floor (or
/// the walls' tops, if higher).
Box3 domain_around(const Geometry3& g, double x_lo, double x_hi, double z_lo, double z_hi, double wall_top) {
  const double margin = g.boundary_layers * g.particle_spacing + 2.0 * g.smoothing_length();
  const double soil_height = g.surface_level - g.floor_level;
  return {{x_lo - margin, g.floor_level - margin, z_lo - margin},
          {x_hi + margin, std::max(g.floor_level + 2.0 * soil_height, wall_top + margin), z_hi + margin}};
}

namespace {

/// particle_spacing, smoothing_ratio, end_time and boundary_layers.
void read_resolution_3d(const TableReader& t, Geometry3& g, double width) {
  const Resolution r = read_resolution(t, Range::open(0.0, std::min(width, g.column_height) / 4));
  g.particle_spacing = r.particle_spacing, g.smoothing_ratio = r.smoothing_ratio, g.end_time = r.end_time;
  g.boundary_layers = read_boundary_layers(t, g.smoothing_ratio);
}

/// column_radius, column_height, symmetry, floor_radius: the cylinder on its floor, with its
/// symmetry planes.
void read_axisymmetric_column(const TableReader& t, const std::string& source, Geometry3& g) {
  g.shape = Geometry3::Shape::AxisymmetricColumn;
  g.column_radius = t.number("column_radius", Range::positive(), "m");
  g.column_height = t.number("column_height", Range::positive(), "m");
  read_resolution_3d(t, g, g.column_radius);
  const double dx = g.particle_spacing;
  require_whole_spacings(t, "column_radius", g.column_radius, dx);
  require_whole_spacings(t, "column_height", g.column_height, dx);
  const std::string symmetry = t.choice_or("symmetry", "quarter", {"quarter", "half", "none"});
  g.symmetry = symmetry == "quarter" ? ColumnSymmetry::Quarter
               : symmetry == "half"  ? ColumnSymmetry::Half
                                     : ColumnSymmetry::None;
  g.floor_radius = t.number_or("floor_radius", default_floor_radius(g.column_radius, g.column_height, dx),
                               Range::open(g.column_radius + dx, 1e3), "m");
  g.floor_length = 0.0, g.column_width = 0.0, g.slab_thickness = 0.0;
  g.wall_withdrawal = WallWithdrawal::None;
  g.azimuth_span_deg = g.symmetry == ColumnSymmetry::Quarter ? 90.0
                       : g.symmetry == ColumnSymmetry::Half  ? 180.0
                                                             : 360.0;
  // The soil is the cylinder r0 × H0 standing on the floor y = 0, filled with whole cells: nodes
  // ((i + ½)Δp, (j + ½)Δp, (k + ½)Δp), none on a symmetry plane, the free surface H0 a half
  // spacing above the top row. Lube et al.'s a = H0/r0 is then the soil's own aspect ratio (nodes at
  // jΔp from a floor Δp/2 below the first row would make the soil H0 + Δp tall).
  g.floor_level = 0.0;
  g.base_level = 0.5 * dx;
  g.surface_level = g.column_height;
  const ColumnCylinder cells{.radius = g.column_radius, .height = g.column_height, .symmetry = g.symmetry};
  g.regions = {{.shape = cells, .material = "", .name = "[scene] column"}};
  g.lattice = Lattice3{{0.5 * dx, 0.5 * dx, 0.5 * dx}, dx};
  g.deposit_axis = {.point = {0.0, g.floor_level, 0.0},
                    .up = kUp,
                    .azimuth_zero = {1.0, 0.0, 0.0},
                    .azimuth_quarter = {0.0, 0.0, 1.0}};

  const double R = g.floor_radius, y = g.floor_level;
  const double x_lo = g.symmetry == ColumnSymmetry::Quarter ? 0.0 : -R;
  const double z_lo = g.symmetry == ColumnSymmetry::None ? -R : 0.0;
  const double top =
      g.column_height + 2.0 * g.smoothing_length();  // 2h above the soil, as the 2D column's walls
  g.walls.push_back(
      wall({x_lo, y, z_lo}, {0.0, 0.0, R - z_lo}, {R - x_lo, 0.0, 0.0}, WallKind::NoSlip, "floor", source));
  if (g.symmetry == ColumnSymmetry::Quarter)
    g.walls.push_back(symmetry_plane({0.0, y, z_lo}, {0.0, top - y, 0.0}, {0.0, 0.0, R - z_lo}, "symmetry_x", source));
  if (g.symmetry != ColumnSymmetry::None)
    g.walls.push_back(symmetry_plane({x_lo, y, 0.0}, {R - x_lo, 0.0, 0.0}, {0.0, top - y, 0.0}, "symmetry_z", source));
  g.domain = domain_around(g, x_lo, R, z_lo, R, top);
}

/// The 2D column's keys (column_width, column_height, wall_withdrawal, floor_length) and
/// slab_thickness: the column extruded between the free-slip planes z = 0 and z = T.
void read_slab(const TableReader& t, const std::string& source, Geometry3& g) {
  g.shape = Geometry3::Shape::Slab;
  g.column_width = t.number("column_width", Range::positive(), "m");
  g.column_height = t.number("column_height", Range::positive(), "m");
  g.slab_thickness = t.number("slab_thickness", Range::positive(), "m");
  read_resolution_3d(t, g, g.column_width);
  const double dx = g.particle_spacing;
  // The 2D column's levels: the first row at y = 0, the floor surface half a spacing below it, the
  // free surface half a spacing above the top row (the paper's layout, geometry/column.h).
  g.floor_level = -0.5 * dx;
  g.base_level = 0.0;
  g.surface_level = g.column_height + 0.5 * dx;
  check_spacing_divides_column(t, g.column_width, g.column_height, dx);
  require_whole_spacings(t, "slab_thickness", g.slab_thickness, dx);
  const ColumnRelease release = read_column_release(t, g.column_width);
  g.wall_withdrawal = release.withdrawal, g.lift_speed = release.lift_speed, g.floor_length = release.floor_length;
  g.column_radius = 0.0, g.floor_radius = 0.0;
  g.symmetry = ColumnSymmetry::None;
  g.azimuth_span_deg = 0.0;
  const double W = g.column_width, H = g.column_height, T = g.slab_thickness;
  g.regions = {{.shape = make_extrusion({{0.0, 0.0}, {W, 0.0}, {W, H}, {0.0, H}}, 0.0, T, source + ": the slab"),
                .material = "",
                .name = "[scene] slab"}};
  // Nodes (iΔp, jΔp, (k + ½)Δp): the 2D column's in x and y, none on the planes z = 0 and z = T.
  g.lattice = Lattice3{{0.0, 0.0, 0.5 * dx}, dx};
  g.deposit_axis = {.point = {W, g.floor_level, 0.0},
                    .up = kUp,
                    .azimuth_zero = {-1.0, 0.0, 0.0},
                    .azimuth_quarter = {0.0, 0.0, 1.0}};

  // As the 2D column (geometry/column.h): the floor y = −Δp/2 from W − floor_length − Δp/2 to the
  // fixed wall x = W + Δp/2, the removable wall x = −Δp/2, the walls up to H + 2h + Δp/2.
  const double y = g.floor_level, x_wall = W + 0.5 * dx, x_lo = W - g.floor_length - 0.5 * dx;
  const double top = H + 2.0 * g.smoothing_length() + 0.5 * dx, up = top - y, along = x_wall - x_lo;
  g.walls.push_back(
      wall({x_lo, y, 0.0}, {0.0, 0.0, T}, {along, 0.0, 0.0}, WallKind::NoSlip, "floor", source));
  g.walls.push_back(
      wall({x_wall, y, 0.0}, {0.0, 0.0, T}, {0.0, up, 0.0}, WallKind::FreeSlip, "fixed_wall", source));
  (g.wall_withdrawal != WallWithdrawal::Instant ? g.walls : g.withdrawn_walls)
      .push_back(wall({-0.5 * dx, y, 0.0}, {0.0, up, 0.0}, {0.0, 0.0, T}, WallKind::FreeSlip,
                      "removable_wall", source));
  if (g.wall_withdrawal == WallWithdrawal::Lift) {
    // The 2D column's gate (geometry/column.cpp): up at lift_speed until its lower end, from −Δp/2,
    // has passed H + 2h + Δp, then removed.
    const double clear = (H + 2.0 * g.smoothing_length() + dx + 0.5 * dx) / g.lift_speed;
    g.walls.back().motion = {
        .removed_at = clear, .velocity = {0.0, g.lift_speed, 0.0}, .start = 0.0, .end = clear};
  }
  g.walls.push_back(symmetry_plane({x_lo, y, 0.0}, {along, 0.0, 0.0}, {0.0, up, 0.0}, "symmetry_z", source));
  g.walls.push_back(symmetry_plane({x_lo, y, T}, {0.0, up, 0.0}, {along, 0.0, 0.0}, "symmetry_far", source));
  g.domain = domain_around(g, x_lo, x_wall, 0.0, T, top);
}

Geometry3 read_geometry(const TableReader& t, const std::string& source, Vec3 gravity) {
  const bool radius = t.has("column_radius"), slab = t.has("column_width") || t.has("slab_thickness");
  if (radius && slab)
    t.fail(
        t.has("column_width") ? "column_width" : "slab_thickness",
        "and column_radius exclude each other: column_radius makes an axisymmetric column, column_width and "
        "slab_thickness a slab");
  if (!radius && !slab)
    t.fail("column_radius",
           "is missing: a 3D scene is an axisymmetric column (column_radius, column_height), a slab "
           "(column_width, column_height, slab_thickness) or [[regions]]");
  if (t.has("lattice_origin")) t.fail("lattice_origin", "is fixed by the 3D shorthand's keys");
  Geometry3 g{};
  g.gravity = gravity;
  if (radius)
    read_axisymmetric_column(t, source, g);
  else
    read_slab(t, source, g);
  return g;
}

}  // namespace

Scene3 read_scene_3d(const toml::table& root, const std::string& source) {
  const bool regions = root.get("regions") != nullptr;
  if (root.get("deposit") && !regions)
    throw ParameterError(source +
                         ": [deposit] is not read in a 3D shorthand scene (the axisymmetric column measures its deposit "
                         "from its axis, the slab from its fixed wall); a scene of [[regions]] takes [deposit] axis");
  static constexpr std::string_view kTables[] = {"scene",   "initial", "material", "materials", "regions",   "numerics",
                                                 "output",  "deposit", "gauges",   "boundaries"};
  check_tables(root, source, kTables);
  if (scene_dimension(root, source) != 3)
    throw ParameterError(source +
                         ": a 2D scene ([scene] dimension = 2 or absent): load it with load_scene or "
                         "load_any_scene; a 3D scene says [scene] dimension = 3");
  const SceneTables tables(root, source);
  if (!regions && !tables.materials.names.front().empty())
    throw ParameterError(source +
                         ": [materials.NAME] tables need [[regions]] that name them; the 3D shorthands "
                         "(column_radius, column_width) hold one soil, given by [material]");
  const TableReader& t = tables.scene;
  (void)t.integer_or("dimension", 3, 3, 3);
  toml::table extra;
  toml::array regions_resolved;
  const Vec3 gravity = read_gravity(t, tables.scene_table, extra);
  Geometry3 geometry{};
  std::vector<int> region_material{0};
  std::vector<std::size_t> used{0};
  if (regions) {
    geometry.gravity = gravity;
    read_regions_geometry(t, tables.scene_table, root, geometry, tables.materials.names, extra, regions_resolved);
    region_material.clear();
    used = materials_in_use(geometry.regions, tables.materials.names, region_material);
  } else {
    geometry = read_geometry(t, source, gravity);
  }
  const toml::array boundaries = read_boundaries_3d(root, source, geometry.walls, geometry.withdrawn_walls);
  if (!boundaries.empty())
    geometry.domain = domain_around_walls(
        geometry.domain, geometry.walls,
        geometry.boundary_layers * geometry.particle_spacing + 2.0 * geometry.smoothing_length());
  const SoilColumn soil{.gravity = geometry.gravity_magnitude(),
                        .height = geometry.column_height,
                        .spacing = geometry.particle_spacing,
                        .end_time = geometry.end_time,
                        .smallest_lateral_stress_ratio = [&](const Material& m) {
                          return smallest_admissible_lateral_stress_ratio_3d(m, geometry);
                        }};
  Scene3 scene{read_settings(tables, used, soil), geometry, {}, std::move(region_material)};
  toml::table deposit_resolved;
  if (regions) read_deposit_3d(root, source, scene.geometry, deposit_resolved);
  toml::array gauges_resolved;
  scene.gauges = read_gauges<3>(root, source, gauges_resolved);
  reject_unknown_keys(tables);
  check_unused_materials(tables, used);
  record_settings(tables, extra, scene.resolved);
  if (regions) scene.resolved.insert("regions", std::move(regions_resolved));
  if (regions && scene.geometry.deposit_measured) scene.resolved.insert("deposit", std::move(deposit_resolved));
  if (!gauges_resolved.empty()) scene.resolved.insert("gauges", std::move(gauges_resolved));
  if (!boundaries.empty()) scene.resolved.insert("boundaries", boundaries);
  return scene;
}

namespace {
/// Reads `root` after the overrides (which may set scene.dimension) as the scene of its dimension.
AnyScene read_any(toml::table& root, const std::string& source, std::span<const std::string> overrides) {
  for (const std::string& assignment : overrides) apply_override(root, assignment);
  AnyScene scene = blaming_overrides(overrides, [&]() -> AnyScene {
    if (scene_dimension(root, source) == 3) return read_scene_3d(root, source);
    return read_scene(root, source);
  });
  std::visit([&](SceneSettings& s) { s.overrides.assign(overrides.begin(), overrides.end()); }, scene);
  return scene;
}
}  // namespace

Scene3 load_scene_3d(const std::string& path, std::span<const std::string> overrides) {
  toml::table root = parse_toml_file(path);
  return read_overridden(root, overrides, [&](const toml::table& r) { return read_scene_3d(r, path); });
}

Scene3 parse_scene_3d(const std::string& text, const std::string& source,
                      std::span<const std::string> overrides) {
  toml::table root = parse_text(text, source);
  return read_overridden(root, overrides, [&](const toml::table& r) { return read_scene_3d(r, source); });
}

AnyScene load_any_scene(const std::string& path, std::span<const std::string> overrides) {
  toml::table root = parse_toml_file(path);
  return read_any(root, path, overrides);
}

AnyScene parse_any_scene(const std::string& text, const std::string& source,
                         std::span<const std::string> overrides) {
  toml::table root = parse_text(text, source);
  return read_any(root, source, overrides);
}

std::string scene_toml(const Scene3& scene) {
  std::ostringstream out;
  out << toml::toml_formatter(scene.resolved);
  return out.str() + "\n";
}

std::string scene_json(const Scene3& scene) {
  std::ostringstream out;
  out << toml::json_formatter(scene.resolved);
  return out.str();
}

}  // namespace soilsph::sph
