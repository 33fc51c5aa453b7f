#include "sph/scene.h"

#include "constitutive/material_limits.h"

#include "sph/geometry/column.h"
#include "sph/geometry/read_layout.h"
#include "sph/initial_state.h"
#include "sph/read_measures.h"
#include "sph/scene_sections.h"

#include <algorithm>
#include <memory>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace soilsph::sph {

using namespace scene_sections;

namespace {

/// The [scene] keys every scene has: spacing, smoothing, duration, gravity, ghost layers.
void read_space_and_time(const TableReader& t, const toml::table& table, Geometry& g, toml::table& extra,
                            Range spacing_range) {
  const Resolution r = read_resolution(t, spacing_range);
  g.particle_spacing = r.particle_spacing;
  g.smoothing_ratio = r.smoothing_ratio;
  g.end_time = r.end_time;
  // Up to 1000 g: a geotechnical centrifuge reaches a few hundred g. A number g is (0, −g).
  if (const toml::node* node = table.get("gravity"); node && node->is_array()) {
    t.accept({"gravity"});
    g.gravity = read_vector(*node, t.source() + ": [scene] gravity", "m/s^2");
    if (g.gravity_magnitude() > 1e4)
      t.fail("gravity", "has magnitude " + format_number(g.gravity_magnitude()) + " (allowed: <= 10000 m/s^2)");
    extra.insert("gravity", toml::array{g.gravity.x, g.gravity.y});
  } else {
    g.gravity = {0.0, -t.number("gravity", Range::closed(0.0, 1e4), "m/s^2")};
  }
  g.boundary_layers = read_boundary_layers(t, g.smoothing_ratio);
}

/// The column shorthand (geometry/column.h), plus any [[boundaries]] the scene adds (e.g. a gate).
void read_column(const TableReader& t, const toml::table& table, const toml::table& root, Geometry& g,
                 toml::table& extra) {
  g.column = true;
  g.column_width = t.number("column_width", Range::positive(), "m");
  g.column_height = t.number("column_height", Range::positive(), "m");
  read_space_and_time(t, table, g, extra, Range::open(0.0, std::min(g.column_width, g.column_height) / 4));
  check_spacing_divides_column(t, g.column_width, g.column_height, g.particle_spacing);
  const ColumnRelease release = read_column_release(t, g.column_width);
  g.wall_withdrawal = release.withdrawal, g.lift_speed = release.lift_speed, g.floor_length = release.floor_length;
  if (t.has("lattice_origin")) t.fail("lattice_origin", "is fixed at [0, 0] by the column keys (column_width, ...)");
  g.layout = column_layout({g.column_width, g.column_height, g.particle_spacing, g.smoothing_length(), g.floor_length,
                            g.boundary_layers, g.wall_withdrawal == WallWithdrawal::Instant,
                            g.wall_withdrawal == WallWithdrawal::Lift ? g.lift_speed : 0.0},
                           "");
  const toml::array added = read_boundaries(root, t.source(), g.layout.walls);
  if (!added.empty()) extra.insert("boundaries", added);
  g.soil_extent = {.largest_x = g.column_width, .height = g.column_height};
  g.surface_level = g.column_height + 0.5 * g.particle_spacing;  // the top of the top row's cells
  g.base_level = 0.0;
}

/// The top of a region along −g, the geostatic surface: its outline's highest point; for imported
/// particles the highest particle + Δp/2 (the top of its cell, as a box's side).
double region_top(const Geometry& g, const Region& r, double dx) {
  double top = -std::numeric_limits<double>::infinity();
  if (r.shape == Region::Shape::Particles) {
    for (const Vec2& p : r.particles) top = std::max(top, g.height(p));
    return top + 0.5 * dx;
  }
  for (const Vec2& v : r.outline) top = std::max(top, g.height(v));
  return top;
}

/// [[regions]] and [[boundaries]] (geometry/read_layout.h).
void read_regions(const TableReader& t, const toml::table& table, const toml::table& root, Geometry& g,
                  toml::table& extra, const std::vector<std::string>& materials) {
  g.column = false;
  read_space_and_time(t, table, g, extra, Range::open(0.0, 1e3));
  const double dx = g.particle_spacing;
  Vec2 origin{0.5 * dx, 0.5 * dx};  // cell edges on multiples of the spacing
  if (const toml::node* node = table.get("lattice_origin")) {
    t.accept({"lattice_origin"});
    origin = read_vector(*node, t.source() + ": [scene] lattice_origin", "m");
  }
  extra.insert("lattice_origin", toml::array{origin.x, origin.y});
  ReadLayout read = read_layout(root, t.source(), dx, origin, materials);
  g.layout = std::move(read.layout);
  extra.insert("regions", std::move(read.regions));
  if (!read.boundaries.empty()) extra.insert("boundaries", std::move(read.boundaries));
  g.wall_withdrawal = WallWithdrawal::None;
  g.floor_length = 0.0;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double top = -inf, bottom = inf, right = -inf;
  for (const Region& r : g.layout.regions) {
    top = std::max(top, region_top(g, r, dx));
    for (const Vec2& v : r.outline) {
      bottom = std::min(bottom, g.height(v));
      right = std::max(right, v.x);
    }
  }
  g.surface_level = top;
  g.base_level = bottom + 0.5 * dx;
  g.soil_extent = {.largest_x = right - 0.5 * dx, .height = std::max(top - 0.5 * dx - g.base_level, dx)};
}

}  // namespace

ColumnRelease read_column_release(const TableReader& t, double column_width) {
  const std::string withdrawal = t.choice("wall_withdrawal", {"instant", "none", "lift"});
  ColumnRelease r{.withdrawal = withdrawal == "instant" ? WallWithdrawal::Instant
                                : withdrawal == "none"  ? WallWithdrawal::None
                                                        : WallWithdrawal::Lift,
                  .lift_speed = 0.0,
                  .floor_length = 0.0};
  if (r.withdrawal == WallWithdrawal::Lift)
    r.lift_speed = t.number("lift_speed", Range::open(0.0, 1e3), "m/s");
  else if (t.has("lift_speed"))
    t.fail("lift_speed", "needs wall_withdrawal = \"lift\" (the gate's speed)");
  r.floor_length = t.number_or("floor_length", 6.0 * column_width, Range::open(column_width, 1e3), "m");
  return r;
}

namespace {
/// The materials the regions use, as indices into `m`, in the order of their first use; each
/// region's index into that list in `region_material`.
std::vector<std::size_t> materials_in_use(const Geometry& g, const MaterialTables& m, std::vector<int>& region_material) {
  std::vector<std::size_t> used;
  for (const Region& r : g.layout.regions) {
    const auto table = static_cast<std::size_t>(std::find(m.names.begin(), m.names.end(), r.material) - m.names.begin());
    auto at = std::find(used.begin(), used.end(), table);
    if (at == used.end()) at = used.insert(used.end(), table);
    region_material.push_back(static_cast<int>(at - used.begin()));
  }
  return used;
}
}  // namespace

Scene read_scene(const toml::table& root, const std::string& source) {
  static constexpr std::string_view kTables[] = {"scene",      "initial",  "material", "materials", "regions",
                                                 "boundaries", "numerics", "output",   "deposit",   "gauges"};
  check_tables(root, source, kTables);
  if (scene_dimension(root, source) == 3)
    throw ParameterError(source + ": [scene] dimension = 3 makes a 3D scene, which the 2D reader does not take: "
                         "load it with load_scene_3d or load_any_scene (sph/scene_3d.h)");
  const SceneTables tables(root, source);
  const TableReader& scene = tables.scene;
  const toml::table& deposit_table = section(root, source, "deposit");
  const TableReader deposit(deposit_table, source, "deposit");
  if (scene.has("dimension")) (void)scene.integer_or("dimension", 2, 2, 2);  // recorded where given

  Geometry geometry{};
  toml::table extra;  // what [scene] and the layout add to the scene as run beyond TableReader's keys
  const bool column_keys = scene.has("column_width") || scene.has("column_height");
  if (root.get("regions") && column_keys)
    scene.fail(scene.has("column_width") ? "column_width" : "column_height",
               "and [[regions]] exclude each other: the column keys are a shorthand for one box region");
  if (root.get("regions")) {
    read_regions(scene, tables.scene_table, root, geometry, extra, tables.materials.names);
  } else {
    if (tables.materials.names.size() != 1 || !tables.materials.names.front().empty())
      throw ParameterError(source + ": [materials.NAME] tables need [[regions]] that name them; the column keys use [material]");
    read_column(scene, tables.scene_table, root, geometry, extra);
  }
  std::vector<int> region_material;
  const std::vector<std::size_t> used = materials_in_use(geometry, tables.materials, region_material);
  const SoilColumn soil{
      .gravity = geometry.gravity_magnitude(),
      .height = geometry.soil_extent.height,
      .spacing = geometry.particle_spacing,
      .end_time = geometry.end_time,
      .smallest_lateral_stress_ratio = [&](const Material& m) { return smallest_admissible_lateral_stress_ratio(m, geometry); }};
  Scene result{read_settings(tables, used, soil), geometry, std::move(region_material), {}, {}};
  reject_unknown_keys(tables);
  toml::table deposit_resolved;
  toml::array gauges_resolved;
  result.deposit = read_deposit(deposit, deposit_table, root.get("deposit") != nullptr, result.geometry, deposit_resolved);
  result.gauges = read_gauges(root, source, gauges_resolved);
  check_unused_materials(tables, used);
  toml::table scene_extra;
  for (const char* key : {"gravity", "lattice_origin"})
    if (const toml::node* v = extra.get(key)) scene_extra.insert(key, *v);
  record_settings(tables, scene_extra, result.resolved);
  for (const char* key : {"regions", "boundaries"})
    if (const toml::node* v = extra.get(key)) result.resolved.insert(key, *v);
  if (result.deposit.defined) result.resolved.insert("deposit", std::move(deposit_resolved));
  if (!gauges_resolved.empty()) result.resolved.insert("gauges", std::move(gauges_resolved));
  return result;
}

Scene load_scene(const std::string& path, std::span<const std::string> overrides) {
  toml::table root = parse_toml_file(path);
  return read_overridden(root, overrides, [&](const toml::table& r) { return read_scene(r, path); });
}

Scene parse_scene(const std::string& text, const std::string& source, std::span<const std::string> overrides) {
  toml::table root = parse_text(text, source);
  return read_overridden(root, overrides, [&](const toml::table& r) { return read_scene(r, source); });
}

std::string scene_toml(const Scene& scene) {
  std::ostringstream out;
  out << toml::toml_formatter(scene.resolved);
  return out.str() + "\n";
}

std::string scene_json(const Scene& scene) {
  std::ostringstream out;
  out << toml::json_formatter(scene.resolved);
  return out.str();
}

}  // namespace soilsph::sph
