#include "sph/scene.h"

#include "constitutive/material_limits.h"

#include "sph/geometry/column.h"
#include "sph/geometry/read_layout.h"
#include "sph/initial_state.h"
#include "sph/read_measures.h"

#include <algorithm>
#include <memory>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace soilsph::sph {

namespace {

const toml::table& section(const toml::table& root, const std::string& source, std::string_view name) {
  static const toml::table empty;
  const toml::node* node = root.get(name);
  if (!node) return empty;
  if (!node->is_table()) throw ParameterError(source + ": [" + std::string(name) + "] must be a table");
  return *node->as_table();
}

/// The lattice must fill the column exactly: a spacing that leaves a remainder builds a narrower or
/// lower column than the one described (0.003 m on 4 × 6 cm gave 3.9 cm, with the runout still
/// measured from 4 cm). The error names the nearest spacings that divide both sides.
void check_spacing_divides_column(const TableReader& t, const Geometry& g) {
  const auto divides = [](double length, double spacing) {
    const double n = length / spacing;
    return std::abs(n - std::round(n)) <= 1e-6 * n;
  };
  const double dx = g.particle_spacing;
  if (divides(g.column_width, dx) && divides(g.column_height, dx)) return;
  double below = 0.0, above = 0.0;  // the nearest spacings W/m that also divide H
  const double intervals = g.column_width / dx;
  for (double m = 1.0; m <= 4.0 * intervals + 4.0 && m <= 1e6; ++m) {
    const double s = g.column_width / m;
    if (!divides(g.column_height, s)) continue;
    if (s < dx && below == 0.0) below = s;
    if (s > dx) above = s;
  }
  std::ostringstream msg;
  msg << dx << " m does not divide the column (" << g.column_width << " m x " << g.column_height
      << " m is " << g.column_width / dx << " x " << g.column_height / dx << " spacings)";
  if (below > 0.0 || above > 0.0) {
    msg << "; the nearest spacings that do:";
    if (above > 0.0) msg << " " << above << " m";
    if (above > 0.0 && below > 0.0) msg << " and";
    if (below > 0.0) msg << " " << below << " m";
  }
  t.fail("particle_spacing", msg.str());
}

/// The [scene] keys every scene has: spacing, smoothing, duration, gravity, ghost layers.
void read_space_and_time(const TableReader& t, const toml::table& table, Geometry& g, toml::table& extra,
                            Range spacing_range) {
  g.particle_spacing = t.number("particle_spacing", spacing_range, "m");
  g.smoothing_ratio = t.number("smoothing_ratio", Range::closed(1.0, 2.0));
  g.end_time = t.number("end_time", Range::positive(), "s");
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
  // Enough layers to fill the support 2h of a soil particle sitting on the wall.
  const auto full_support = static_cast<long long>(std::ceil(2.0 * g.smoothing_ratio - 1e-9));
  g.boundary_layers = static_cast<int>(t.integer_or("boundary_layers", full_support, full_support, 10));
}

/// The column shorthand (geometry/column.h), plus any [[boundaries]] the scene adds (e.g. a gate).
void read_column(const TableReader& t, const toml::table& table, const toml::table& root, Geometry& g,
                 toml::table& extra) {
  g.column = true;
  g.column_width = t.number("column_width", Range::positive(), "m");
  g.column_height = t.number("column_height", Range::positive(), "m");
  read_space_and_time(t, table, g, extra, Range::open(0.0, std::min(g.column_width, g.column_height) / 4));
  check_spacing_divides_column(t, g);
  const std::string withdrawal = t.choice("wall_withdrawal", {"instant", "none", "lift"});
  g.wall_withdrawal = withdrawal == "instant" ? WallWithdrawal::Instant
                      : withdrawal == "none"  ? WallWithdrawal::None
                                              : WallWithdrawal::Lift;
  if (g.wall_withdrawal == WallWithdrawal::Lift)
    g.lift_speed = t.number("lift_speed", Range::open(0.0, 1e3), "m/s");
  else if (t.has("lift_speed"))
    t.fail("lift_speed", "needs wall_withdrawal = \"lift\" (the gate's speed)");
  g.floor_length = t.number_or("floor_length", 6.0 * g.column_width, Range::open(g.column_width, 1e3), "m");
  if (t.has("lattice_origin")) t.fail("lattice_origin", "is fixed at [0, 0] by the column keys (column_width, ...)");
  g.layout = column_layout({g.column_width, g.column_height, g.particle_spacing, g.smoothing_length(), g.floor_length,
                            g.boundary_layers, g.wall_withdrawal == WallWithdrawal::Instant,
                            g.wall_withdrawal == WallWithdrawal::Lift ? g.lift_speed : 0.0},
                           "");
  const toml::array added = read_boundaries(root, t.source(), g.layout.walls);
  if (!added.empty()) extra.insert("boundaries", added);
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
  g.column_width = right - 0.5 * dx;
  g.column_height = std::max(top - 0.5 * dx - g.base_level, dx);
}

/// Defaults scale with the column (sph/rest.h): 1 % of √(2gH) and √(H/g); without gravity the
/// run has no such scale and does not stop at rest unless asked to (then 1 cm/s and 0.1 s).
RestCriterion read_rest(const TableReader& t, const Geometry& g) {
  const bool falls = g.gravity_magnitude() > 0.0;
  RestCriterion r;
  r.enabled = t.boolean_or("stop_at_rest", falls);
  r.speed = t.number_or("rest_speed", falls ? 0.01 * std::sqrt(2.0 * g.gravity_magnitude() * g.column_height) : 0.01,
                        Range::positive(), "m/s");
  r.duration = t.number_or("rest_duration", falls ? std::sqrt(g.column_height / g.gravity_magnitude()) : 0.1,
                           Range::positive(), "s");
  r.fraction = t.number_or("rest_fraction", 0.99, Range::open_closed(0.5, 1.0));
  return r;
}

/// K0's default and its lower bound for one material (see read_initial).
struct LateralStressRatio {
  double elastic, bound;
  double preferred() const { return std::max(elastic, bound); }
};

LateralStressRatio lateral_stress_ratio_of(const Material& material, const Geometry& geometry) {
  const double nu = std::visit([](const auto& m) { return m.elasticity().poisson_ratio(); }, material);
  return {nu / (1.0 - nu), smallest_admissible_lateral_stress_ratio(material, geometry)};
}

/// The K0 a column may be given: below 1 (the active side) and at least the bound its yield surface
/// sets (0: none). A cone too slender for any K0 < 1 (cohesionless D-P with φ → 0) holds K0 = 1 alone.
Range lateral_stress_ratio_range(double bound) {
  if (!(bound > 0.0)) return Range::open(0.0, 1.0);
  return bound < 1.0 ? Range::closed_open(bound, 1.0) : Range::closed(1.0, 1.0);
}

InitialConditions read_initial(const TableReader& t, const std::vector<Material>& materials,
                               const std::vector<std::string>& names, const Geometry& geometry) {
  // Default K0 = ν/(1−ν): the lateral stress of an elastic column under its own weight between
  // rigid, frictionless walls (uniaxial strain), so the initial state is an elastic equilibrium.
  // Where the yield surface cannot hold it (D-P with φ below about 30° at ν = 0.3) an elastic-
  // plastic column yields as it is loaded and rests on the surface: the default is then the
  // smallest admissible K0, and every K0 below it is an error that states the bound. With several
  // materials each has its own default; a K0 given in [initial] holds for all and must be
  // admissible for each (its bound is the largest of theirs).
  std::vector<LateralStressRatio> k0;
  double bound = 0.0;
  for (const Material& m : materials) {
    k0.push_back(lateral_stress_ratio_of(m, geometry));
    bound = std::max(bound, k0.back().bound);
  }
  InitialConditions c{};
  if (materials.size() == 1) {
    if (k0[0].bound > k0[0].elastic && !t.has("lateral_stress_ratio"))
      std::cerr << "note: " << t.source() << ": [initial] lateral_stress_ratio defaults to " << k0[0].bound
                << ", the smallest the yield surface holds at the column's base (the elastic nu/(1-nu) = "
                << k0[0].elastic << " lies outside it)\n";
    c.lateral_stress_ratio =
        t.number_or("lateral_stress_ratio", k0[0].preferred(), lateral_stress_ratio_range(bound));
    c.material_lateral_stress_ratio = {c.lateral_stress_ratio};
  } else if (t.has("lateral_stress_ratio")) {  // one K0 for all; without the key each its own (not recorded)
    c.lateral_stress_ratio = t.number("lateral_stress_ratio", lateral_stress_ratio_range(bound));
    c.material_lateral_stress_ratio.assign(materials.size(), c.lateral_stress_ratio);
  } else {
    for (std::size_t k = 0; k < materials.size(); ++k) {
      if (k0[k].bound > k0[k].elastic)
        std::cerr << "note: " << t.source() << ": K0 of [materials." << names[k] << "] defaults to " << k0[k].bound
                  << ", the smallest its yield surface holds at the soil's base (the elastic nu/(1-nu) = "
                  << k0[k].elastic << " lies outside it)\n";
      c.material_lateral_stress_ratio.push_back(k0[k].preferred());
    }
    c.lateral_stress_ratio = c.material_lateral_stress_ratio.front();
  }
  c.overconsolidation_ratio = t.number_or("overconsolidation_ratio", 1.0, Range::closed_open(1.0, 1e3));
  c.preconsolidation_floor = t.number_or("preconsolidation_floor", 100.0, limits::stress_range(), "Pa");
  const std::string stress = t.choice_or("stress", "flat-surface", {"flat-surface", "local-surface", "gravity-loading"});
  c.stress = stress == "local-surface"     ? InitialStress::LocalSurface
             : stress == "gravity-loading" ? InitialStress::GravityLoading
                                           : InitialStress::FlatSurface;
  if (c.stress == InitialStress::GravityLoading) {
    // Defaults: about a tenth of critical damping of the soil's first mode at a few mm spacing
    // (docs/reference/scenes.md); settled at a speed of ~1e-4 sqrt(g H) and a stress drift of 1e-5 rho g H
    // per step.
    c.gravity_loading.damping = t.number_or("gravity_loading_damping", 0.02, Range::open(0.0, 1.0));
    c.gravity_loading.kinetic_tolerance =
        t.number_or("gravity_loading_kinetic_energy", 1e-8, Range::open(0.0, 1.0));
    c.gravity_loading.stress_tolerance = t.number_or("gravity_loading_stress_change", 1e-5, Range::open(0.0, 1.0));
    c.gravity_loading.max_time = t.number_or("gravity_loading_max_time", 2.0, Range::open_closed(0.0, 100.0), "s");
  } else {
    for (const char* key : {"gravity_loading_damping", "gravity_loading_kinetic_energy", "gravity_loading_stress_change",
                            "gravity_loading_max_time"})
      if (t.has(key)) t.fail(key, "needs stress = \"gravity-loading\"");
  }
  return c;
}

Numerics read_numerics(const TableReader& t) {
  Numerics n{};
  n.viscosity_alpha = t.number_or("artificial_viscosity_alpha", 0.1, Range::non_negative());
  n.viscosity_beta = t.number_or("artificial_viscosity_beta", 0.1, Range::non_negative());
  n.artificial_stress = t.boolean_or("artificial_stress", true);
  n.artificial_stress_epsilon = t.number_or("artificial_stress_epsilon", 0.5, Range::closed(0.0, 1.0));
  // n ≥ 1 keeps f^n differentiable at f = 0, which its table needs (stages/kernel_ratio_power.h);
  // the literature uses 2.55 (Bui et al. 2008) to 4 (Gray et al. 2001); 10 bounds the table's error.
  n.artificial_stress_exponent =
      t.number_or("artificial_stress_exponent", 2.55, Range::closed(1.0, 10.0));
  n.cfl = t.number_or("cfl", 0.5, Range::open_closed(0.0, 2.0));  // limit and margin: docs/method/sph.md
  n.velocity_gradient_correction = t.boolean_or("velocity_gradient_correction", false);
  n.ghost_body_force = t.boolean_or("ghost_body_force", true);
  return n;
}

/// `fields` selects the frame datasets (names: kFieldNames in sph/output/frame.h); default: all of them.
OutputSettings read_output(const TableReader& t, double end_time) {
  OutputSettings o{};
  // How many frames that makes is checked with the run's other costs (sph/feasibility.h).
  o.frame_interval = t.number_or("frame_interval", 0.01, Range::open(0.0, end_time * (1 + 1e-9)), "s");
  o.layer_thickness = t.number_or("layer_thickness", 0.01, Range::positive(), "m");
  for (const std::string& name : t.choices_or("fields", kFieldNames, kFieldNames))
    o.fields.insert(*field_named(name));
  // A checkpoint costs about as much as a frame; every 0.1 s keeps what a killed run loses small.
  o.checkpoint_interval = t.number_or("checkpoint_interval", 0.1, Range::positive(), "s");
  // Ten samples per frame: a sample costs about one step's acceleration, once in tens of steps.
  o.history_interval = t.number_or("history_interval", 0.1 * o.frame_interval, Range::closed(0.0, end_time), "s");
  return o;
}

}  // namespace

namespace {
/// The named materials of [materials.NAME] (or the one [material], named "").
struct Materials {
  std::vector<std::string> names;
  std::vector<std::unique_ptr<TableReader>> tables;
};

Materials material_tables(const toml::table& root, const std::string& source) {
  Materials m;
  const bool one = root.get("material") != nullptr, named = root.get("materials") != nullptr;
  if (one == named)
    throw ParameterError(source + (one ? ": give either [material] or [materials.NAME] tables, not both"
                                       : ": no [material] table (or [materials.NAME] tables)"));
  if (one) {
    m.names.push_back("");
    m.tables.push_back(std::make_unique<TableReader>(section(root, source, "material"), source, "material"));
    return m;
  }
  const toml::table& all = section(root, source, "materials");
  if (all.empty()) throw ParameterError(source + ": [materials] holds no [materials.NAME] table");
  for (const auto& [key, node] : all) {
    const std::string name(key.str());
    if (!node.is_table()) throw ParameterError(source + ": [materials] " + name + " must be a table ([materials." + name + "])");
    m.names.push_back(name);
    m.tables.push_back(std::make_unique<TableReader>(*node.as_table(), source, "materials." + name));
  }
  return m;
}

/// The materials the regions use, as indices into `m`, in the order of their first use; each
/// region's index into that list in `region_material`.
std::vector<std::size_t> materials_in_use(const Geometry& g, const Materials& m, std::vector<int>& region_material) {
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
  for (const auto& [key, node] : root) {
    const std::string_view name = key.str();
    if (std::find(std::begin(kTables), std::end(kTables), name) == std::end(kTables))
      throw ParameterError(source + ": [" + std::string(name) +
                           "] is not a known table (allowed: scene, initial, material, materials, regions, "
                           "boundaries, numerics, output, deposit, gauges)");
  }
  if (!root.get("scene")) throw ParameterError(source + ": no [scene] table");
  const Materials materials = material_tables(root, source);

  const toml::table& scene_table = section(root, source, "scene");
  const TableReader scene(scene_table, source, "scene");
  const TableReader initial(section(root, source, "initial"), source, "initial");
  const TableReader numerics(section(root, source, "numerics"), source, "numerics");
  const TableReader output(section(root, source, "output"), source, "output");
  const toml::table& deposit_table = section(root, source, "deposit");
  const TableReader deposit(deposit_table, source, "deposit");

  Geometry geometry{};
  toml::table extra;  // what [scene] and the layout add to the scene as run beyond TableReader's keys
  const bool column_keys = scene.has("column_width") || scene.has("column_height");
  if (root.get("regions") && column_keys)
    scene.fail(scene.has("column_width") ? "column_width" : "column_height",
               "and [[regions]] exclude each other: the column keys are a shorthand for one box region");
  if (root.get("regions")) {
    read_regions(scene, scene_table, root, geometry, extra, materials.names);
  } else {
    if (materials.names.size() != 1 || !materials.names.front().empty())
      throw ParameterError(source + ": [materials.NAME] tables need [[regions]] that name them; the column keys use [material]");
    read_column(scene, scene_table, root, geometry, extra);
  }
  std::vector<int> region_material;
  const std::vector<std::size_t> used = materials_in_use(geometry, materials, region_material);
  const RestCriterion rest = read_rest(scene, geometry);
  std::vector<Material> in_use;
  std::vector<std::string> names_in_use;
  double heaviest = 0.0;
  for (const std::size_t k : used) {
    in_use.push_back(read_material(*materials.tables[k]));
    names_in_use.push_back(materials.names[k]);
    heaviest = std::max(heaviest, density(in_use.back()));
  }
  const double base_stress = heaviest * geometry.gravity_magnitude() * (geometry.column_height + geometry.particle_spacing);
  if (!std::isfinite(base_stress))
    throw ParameterError(source + ": the weight of the column overflows: [material] density x [scene] gravity x "
                         "[scene] column_height is not a finite stress (Pa)");
  Scene result{source,
               {},
               geometry,
               read_initial(initial, in_use, names_in_use, geometry),
               read_numerics(numerics),
               read_output(output, geometry.end_time),
               in_use.front(),
               rest,
               {scene.number_or("max_run_hours", 24.0, Range::positive(), "h")},
               {},
               std::move(in_use),
               std::move(names_in_use),
               std::move(region_material),
               {},
               {}};
  for (const TableReader* t : {&scene, &initial, &numerics, &output}) t->reject_unknown_keys();
  toml::table deposit_resolved;
  toml::array gauges_resolved;
  result.deposit = read_deposit(deposit, deposit_table, root.get("deposit") != nullptr, result.geometry, deposit_resolved);
  result.gauges = read_gauges(root, source, gauges_resolved);
  // Every named material is read (validated) even if unused, so a typo in one is never silent.
  for (std::size_t k = 0; k < materials.tables.size(); ++k)
    if (std::find(used.begin(), used.end(), k) == used.end()) (void)read_material(*materials.tables[k]);
  toml::table scene_resolved = scene.resolved();
  for (const char* key : {"gravity", "lattice_origin"})
    if (const toml::node* v = extra.get(key)) scene_resolved.insert_or_assign(key, *v);
  result.resolved.insert("scene", std::move(scene_resolved));
  for (const TableReader* t : {&initial, &numerics, &output}) result.resolved.insert(t->table_name(), t->resolved());
  if (materials.names.front().empty()) {
    result.resolved.insert("material", materials.tables.front()->resolved());
  } else {
    toml::table named;
    for (std::size_t k = 0; k < materials.tables.size(); ++k) named.insert(materials.names[k], materials.tables[k]->resolved());
    result.resolved.insert("materials", std::move(named));
  }
  for (const char* key : {"regions", "boundaries"})
    if (const toml::node* v = extra.get(key)) result.resolved.insert(key, *v);
  if (result.deposit.defined) result.resolved.insert("deposit", std::move(deposit_resolved));
  if (!gauges_resolved.empty()) result.resolved.insert("gauges", std::move(gauges_resolved));
  return result;
}

namespace {
/// Reads `root` after the overrides; a refusal of the file's keys lists the options applied.
Scene read_overridden(toml::table& root, const std::string& source, std::span<const std::string> overrides) {
  for (const std::string& assignment : overrides) apply_override(root, assignment);
  Scene scene = blaming_overrides(overrides, [&] { return read_scene(root, source); });
  scene.overrides.assign(overrides.begin(), overrides.end());
  return scene;
}
}  // namespace

Scene load_scene(const std::string& path, std::span<const std::string> overrides) {
  toml::table root = parse_toml_file(path);
  return read_overridden(root, path, overrides);
}

Scene parse_scene(const std::string& text, const std::string& source, std::span<const std::string> overrides) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ParameterError(source + ":" + std::to_string(e.source().begin.line) + ": " +
                         std::string(e.description()));
  }
  return read_overridden(root, source, overrides);
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
