#include "sph/read_regions_3d.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "sph/analysis/axisymmetric_deposit.h"
#include "sph/geometry/read_layout.h"
#include "sph/geometry/read_particles_3d.h"
#include "sph/scene_sections.h"

namespace soilsph::sph {

namespace {

toml::array as_array(Vec3 v) {
  return toml::array{v.x, v.y, v.z};
}

/// A region's file, relative to the scene file's folder; recorded as an absolute path, so that a
/// checkpoint's scene finds it.
std::string region_file(const TableReader& t, const toml::table& table, const std::string& what,
                        toml::table& resolved) {
  t.accept({"file"});
  const toml::node* node = table.get("file");
  if (!node || !node->is_string()) t.fail("file", "must be given as a string: " + what);
  std::filesystem::path file(**node->as_string());
  if (file.is_relative()) file = std::filesystem::path(t.source()).parent_path() / file;
  file = std::filesystem::absolute(file).lexically_normal();
  resolved.insert_or_assign("file", file.string());
  return file.string();
}

/// A required [x, y, z] key of a region.
Vec3 vector_key(const TableReader& t, const toml::table& table, std::string_view key,
                const std::string& where) {
  t.accept({key});
  const toml::node* node = table.get(key);
  if (!node) t.fail(key, "is missing ([x, y, z] in m)");
  return read_vector_of<3>(*node, where + " " + std::string(key), "m");
}

/// A box's sides on cell edges of the lattice (as in 2D: it then holds whole cells, ρ × its volume).
SoilBox read_box(const TableReader& t, const toml::table& table, const std::string& where,
                 const Lattice3& lattice, toml::table& resolved) {
  const Vec3 a = vector_key(t, table, "min", where), b = vector_key(t, table, "max", where);
  if (!(b.x > a.x && b.y > a.y && b.z > a.z))
    throw ParameterError(where + " max must exceed min in x, in y and in z (an empty box)");
  const Vec3 o = lattice.origin;
  for (const auto& [key, v] : {std::pair{"min", a}, std::pair{"max", b}}) {
    check_on_cell_edge(where, key, 'x', v.x, o.x, lattice.spacing);
    check_on_cell_edge(where, key, 'y', v.y, o.y, lattice.spacing);
    check_on_cell_edge(where, key, 'z', v.z, o.z, lattice.spacing);
  }
  resolved.insert_or_assign("min", as_array(a));
  resolved.insert_or_assign("max", as_array(b));
  return {Box3{a, b}};
}

ColumnCylinder read_cylinder(const TableReader& t, const toml::table& table, const std::string& where,
                             toml::table& resolved) {
  const Vec3 base = vector_key(t, table, "base_centre", where);
  const double radius = t.number("radius", Range::open(0.0, kLargestCoordinate), "m");
  const double height = t.number("height", Range::open(0.0, kLargestCoordinate), "m");
  const std::string part = t.choice_or("part", "whole", {"whole", "half", "quarter"});
  resolved.insert_or_assign("base_centre", as_array(base));
  return {.radius = radius,
          .height = height,
          .symmetry = part == "quarter" ? ColumnSymmetry::Quarter
                      : part == "half"  ? ColumnSymmetry::Half
                                        : ColumnSymmetry::None,
          .base = base};
}

Extrusion read_extrusion(const TableReader& t, const toml::table& table, const std::string& where,
                         toml::table& resolved) {
  t.accept({"points"});
  std::vector<Vec2> outline = points_of(table, where, 3);
  const Range coordinate = Range::closed(-kLargestCoordinate, kLargestCoordinate);
  const double z_min = t.number("z_min", coordinate, "m"), z_max = t.number("z_max", coordinate, "m");
  toml::array points;
  for (const Vec2& p : outline) points.push_back(toml::array{p.x, p.y});
  resolved.insert_or_assign("points", std::move(points));
  return make_extrusion(std::move(outline), z_min, z_max, where + " points");
}

/// A `shape = "particles"` entry: one region per material its file names (read_particles_3d.h).
std::vector<SoilRegion3> read_cloud(const TableReader& t, const toml::table& table, const std::string& label,
                                    double dx, const std::vector<std::string>& materials,
                                    toml::table& resolved) {
  if (t.has("material"))
    t.fail("material", "is given by the particle file's region column (shape = \"particles\")");
  const std::string file = region_file(t, table, "the CSV file of the particles (x,y,z,region)", resolved);
  t.reject_unknown_keys();
  std::vector<SoilRegion3> regions;
  for (ParticleRegion3& r : read_particle_file_3d(file, "[" + label + "]", dx, t.source(), materials))
    regions.push_back(
        {.shape = ParticleCloud3{std::move(r.positions), r.bounds}, .material = r.material, .name = r.name});
  return regions;
}

std::vector<SoilRegion3> read_region(const toml::table& table, const std::string& label,
                                     const std::string& source, const Lattice3& lattice,
                                     const std::vector<std::string>& materials, toml::table& resolved) {
  const TableReader t(table, source, label);
  const std::string where = source + ": [" + label + "]";
  const std::string shape = t.choice("shape", {"box", "cylinder", "extrusion", "particles", "stl"});
  if (shape == "particles") {
    std::vector<SoilRegion3> cloud = read_cloud(t, table, label, lattice.spacing, materials, resolved);
    resolved.insert("shape", shape);
    return cloud;
  }
  SoilRegion3 region{.shape = SoilBox{}, .material = {}, .name = "[" + label + "]"};
  if (shape == "box") {
    region.shape = read_box(t, table, where, lattice, resolved);
  } else if (shape == "cylinder") {
    region.shape = read_cylinder(t, table, where, resolved);
  } else if (shape == "extrusion") {
    region.shape = read_extrusion(t, table, where, resolved);
  } else {
    const std::string file =
        region_file(t, table, "the STL file of a closed surface (ASCII or binary)", resolved);
    region.shape = load_stl_solid(file, t.number_or("scale", 1.0, Range::open(0.0, 1e6), "m per file unit"));
  }
  if (materials.size() == 1 && !t.has("material")) {
    region.material = materials.front();
  } else {
    std::vector<std::string_view> names(materials.begin(), materials.end());
    region.material = t.choice("material", names);
  }
  t.reject_unknown_keys();
  for (auto&& [key, value] : t.resolved()) resolved.insert_or_assign(key, value);
  return {region};
}

/// The highest cell edge of the lattice (origin + (j + ½)Δp along y) at or below y.
double cell_edge_at_or_below(double y, double origin, double dx) {
  return origin + (std::floor((y - origin) / dx - 0.5 + 1e-6) + 0.5) * dx;
}

}  // namespace

std::vector<SoilRegion3> read_regions_3d(const toml::table& root, const std::string& source,
                                         const Lattice3& lattice, const std::vector<std::string>& materials,
                                         toml::array& resolved) {
  std::vector<SoilRegion3> regions;
  for (const auto& [table, label] : tables_of(root, source, "regions")) {
    toml::table r;
    for (SoilRegion3& region : read_region(*table, label, source, lattice, materials, r))
      regions.push_back(std::move(region));
    resolved.push_back(std::move(r));
  }
  if (regions.empty()) throw ParameterError(source + ": [[regions]] holds no region (no soil)");
  return regions;
}

void read_regions_geometry(const TableReader& t, const toml::table& table, const toml::table& root,
                           Geometry3& g, const std::vector<std::string>& materials, toml::table& extra,
                           toml::array& regions) {
  for (const char* key : {"column_radius", "column_width", "column_height", "slab_thickness"})
    if (t.has(key))
      t.fail(
          key,
          "and [[regions]] exclude each other: the shorthand keys build the soil of an axisymmetric column "
          "or a slab");
  g.shape = Geometry3::Shape::Regions;
  const scene_sections::Resolution r = scene_sections::read_resolution(t, Range::open(0.0, 1e3));
  g.particle_spacing = r.particle_spacing, g.smoothing_ratio = r.smoothing_ratio, g.end_time = r.end_time;
  g.boundary_layers = scene_sections::read_boundary_layers(t, g.smoothing_ratio);
  const double dx = g.particle_spacing;
  Vec3 origin{0.5 * dx, 0.5 * dx, 0.5 * dx};  // cell edges on multiples of the spacing, as in 2D
  if (const toml::node* node = table.get("lattice_origin")) {
    t.accept({"lattice_origin"});
    origin = read_vector_of<3>(*node, t.source() + ": [scene] lattice_origin", "m");
  }
  extra.insert("lattice_origin", as_array(origin));
  g.lattice = Lattice3{origin, dx};
  g.regions = read_regions_3d(root, t.source(), g.lattice, materials, regions);

  // The levels, as a 2D scene of regions takes them: the free surface at the top of the regions
  // (a box's top side, a cloud's highest cell), the base at the lowest soil row.
  constexpr double inf = std::numeric_limits<double>::infinity();
  double top = -inf, base = inf, bottom = inf;
  for (const SoilRegion3& region : g.regions) {
    const Box3 b = region_bounds(region);
    top = std::max(top, b.hi.y);
    bottom = std::min(bottom, b.lo.y);
    base = std::min(base,
                    std::holds_alternative<ParticleCloud3>(region.shape)
                        ? b.lo.y + 0.5 * dx
                        : origin.y + static_cast<double>(g.lattice.first_at_or_above(b.lo.y, origin.y)) * dx);
  }
  g.surface_level = top;
  g.base_level = base;
  g.column_height = std::max(top - 0.5 * dx - base, dx);
  g.column_radius = 0.0, g.column_width = 0.0, g.slab_thickness = 0.0, g.floor_radius = 0.0,
  g.floor_length = 0.0;
  g.symmetry = ColumnSymmetry::None;
  g.wall_withdrawal = WallWithdrawal::None;
  g.azimuth_span_deg = 0.0;
  g.deposit_measured = false;

  // The floor under the lowest soil cell, on a cell edge so that its ghosts continue the lattice.
  const double lowest_cell = base - 0.5 * dx;
  g.floor_level =
      t.number_or("floor_level", cell_edge_at_or_below(std::min(bottom, lowest_cell), origin.y, dx),
                  Range::closed(-kLargestCoordinate, kLargestCoordinate), "m");
  check_on_cell_edge(t.source() + ": [scene]", "floor_level", 'y', g.floor_level, origin.y, dx);
  if (g.floor_level > lowest_cell + 1e-6 * dx)
    t.fail("floor_level", "= " + format_number(g.floor_level) +
                              " m lies above the bottom of the lowest soil cell (y = " +
                              format_number(lowest_cell) + " m; allowed: at or below it)");
  // Twice the runout beyond its foot that Lube et al. (2004) measured for a column of the soil's
  // height, (r∞ − r0) = 1.24 H0 (a ≤ 1.7), plus four spacings, as the axisymmetric column's floor.
  const double margin =
      t.number_or("floor_margin", 2.0 * 1.24 * g.column_height + 4.0 * dx, Range::open(0.0, 1e3), "m");
  add_regions_floor(g, margin, t.source());
}

void add_regions_floor(Geometry3& g, double margin, const std::string& source) {
  Box3 soil = region_bounds(g.regions.front());
  for (const SoilRegion3& region : g.regions) soil = merged(soil, region_bounds(region));
  const double x_lo = soil.lo.x - margin, x_hi = soil.hi.x + margin, z_lo = soil.lo.z - margin,
               z_hi = soil.hi.z + margin, y = g.floor_level;
  // The soil on the side of a × b = (+z) × (+x) = +y: above.
  g.walls = {{.plane = rectangle_wall({x_lo, y, z_lo}, {0.0, 0.0, z_hi - z_lo}, {x_hi - x_lo, 0.0, 0.0},
                                      source + ": the floor"),
              .kind = WallKind::NoSlip,
              .friction_angle = 0.0,
              .label = "floor",
              .motion = {}}};
  g.domain = domain_around(g, x_lo, x_hi, z_lo, z_hi, y);
}

std::vector<std::size_t> materials_in_use(const std::vector<SoilRegion3>& regions,
                                          const std::vector<std::string>& names,
                                          std::vector<int>& region_material) {
  std::vector<std::size_t> used;
  for (const SoilRegion3& r : regions) {
    const auto table =
        static_cast<std::size_t>(std::find(names.begin(), names.end(), r.material) - names.begin());
    auto at = std::find(used.begin(), used.end(), table);
    if (at == used.end()) at = used.insert(used.end(), table);
    region_material.push_back(static_cast<int>(at - used.begin()));
  }
  return used;
}

void read_deposit_3d(const toml::table& root, const std::string& source, Geometry3& g,
                     toml::table& resolved) {
  const toml::table& table = scene_sections::section(root, source, "deposit");
  g.deposit_measured = root.get("deposit") != nullptr;
  if (!g.deposit_measured) return;
  const TableReader t(table, source, "deposit");
  t.accept({"axis"});
  const toml::node* node = table.get("axis");
  if (!node) t.fail("axis", "is missing ([x, z] in m: the vertical axis the runout radius is measured from)");
  const Vec2 axis = read_vector(*node, source + ": [deposit] axis", "m");
  g.azimuth_span_deg = t.number_or("azimuth_span", 360.0, Range::open_closed(0.0, 360.0), "degrees");
  t.reject_unknown_keys();
  g.deposit_axis = {.point = {axis.x, g.floor_level, axis.y},
                    .up = {0.0, 1.0, 0.0},
                    .azimuth_zero = {1.0, 0.0, 0.0},
                    .azimuth_quarter = {0.0, 0.0, 1.0}};
  resolved = t.resolved();
  resolved.insert_or_assign("axis", toml::array{axis.x, axis.y});
}

}  // namespace soilsph::sph
