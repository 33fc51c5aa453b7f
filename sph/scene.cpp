#include "sph/scene.h"

#include "constitutive/material_limits.h"

#include "sph/initial_state.h"

#include <algorithm>
#include <cmath>
#include <iostream>
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

Geometry read_geometry(const TableReader& t) {
  Geometry g{};
  g.column_width = t.number("column_width", Range::positive(), "m");
  g.column_height = t.number("column_height", Range::positive(), "m");
  g.particle_spacing =
      t.number("particle_spacing", Range::open(0.0, std::min(g.column_width, g.column_height) / 4), "m");
  check_spacing_divides_column(t, g);
  g.smoothing_ratio = t.number("smoothing_ratio", Range::closed(1.0, 2.0));
  g.end_time = t.number("end_time", Range::positive(), "s");
  // Up to 1000 g: a geotechnical centrifuge reaches a few hundred g.
  g.gravity = t.number("gravity", Range::closed(0.0, 1e4), "m/s^2");
  g.wall_withdrawal = t.choice("wall_withdrawal", {"instant", "none"}) == "instant" ? WallWithdrawal::Instant
                                                                                    : WallWithdrawal::None;
  // Enough layers to fill the support 2h of a soil particle sitting on the wall.
  const auto full_support = static_cast<long long>(std::ceil(2.0 * g.smoothing_ratio - 1e-9));
  g.boundary_layers = static_cast<int>(t.integer_or("boundary_layers", full_support, full_support, 10));
  g.floor_length = t.number_or("floor_length", 6.0 * g.column_width, Range::open(g.column_width, 1e3), "m");
  return g;
}

/// Defaults scale with the column (sph/rest.h): 1 % of √(2gH) and √(H/g); without gravity the
/// run has no such scale and does not stop at rest unless asked to (then 1 cm/s and 0.1 s).
RestCriterion read_rest(const TableReader& t, const Geometry& g) {
  const bool falls = g.gravity > 0.0;
  RestCriterion r;
  r.enabled = t.boolean_or("stop_at_rest", falls);
  r.speed = t.number_or("rest_speed", falls ? 0.01 * std::sqrt(2.0 * g.gravity * g.column_height) : 0.01,
                        Range::positive(), "m/s");
  r.duration = t.number_or("rest_duration", falls ? std::sqrt(g.column_height / g.gravity) : 0.1,
                           Range::positive(), "s");
  r.fraction = t.number_or("rest_fraction", 0.99, Range::open_closed(0.5, 1.0));
  return r;
}

InitialConditions read_initial(const TableReader& t, const Material& material, const Geometry& geometry) {
  // Default K0 = ν/(1−ν): the lateral stress of an elastic column under its own weight between
  // rigid, frictionless walls (uniaxial strain), so the initial state is an elastic equilibrium.
  // Where the yield surface cannot hold it (D-P with φ below about 30° at ν = 0.3) an elastic-
  // plastic column yields as it is loaded and rests on the surface: the default is then the
  // smallest admissible K0, and every K0 below it is an error that states the bound.
  const double nu = std::visit([](const auto& m) { return m.elasticity().poisson_ratio(); }, material);
  const double elastic = nu / (1.0 - nu), bound = smallest_admissible_lateral_stress_ratio(material, geometry);
  if (bound > elastic && !t.has("lateral_stress_ratio"))
    std::cerr << "note: " << t.source() << ": [initial] lateral_stress_ratio defaults to " << bound
              << ", the smallest the yield surface holds at the column's base (the elastic nu/(1-nu) = " << elastic
              << " lies outside it)\n";
  InitialConditions c{};
  c.lateral_stress_ratio = t.number_or("lateral_stress_ratio", std::max(elastic, bound),
                                       bound > 0.0 ? Range::closed_open(bound, 1.0) : Range::open(0.0, 1.0));
  c.overconsolidation_ratio = t.number_or("overconsolidation_ratio", 1.0, Range::closed_open(1.0, 1e3));
  c.preconsolidation_floor = t.number_or("preconsolidation_floor", 100.0, limits::stress_range(), "Pa");
  return c;
}

Numerics read_numerics(const TableReader& t) {
  Numerics n{};
  n.viscosity_alpha = t.number_or("artificial_viscosity_alpha", 0.1, Range::non_negative());
  n.viscosity_beta = t.number_or("artificial_viscosity_beta", 0.1, Range::non_negative());
  n.artificial_stress = t.boolean_or("artificial_stress", true);
  n.artificial_stress_epsilon = t.number_or("artificial_stress_epsilon", 0.5, Range::closed(0.0, 1.0));
  n.artificial_stress_exponent = t.number_or("artificial_stress_exponent", 2.55, Range::positive());
  n.cfl = t.number_or("cfl", 0.5, Range::open_closed(0.0, 2.0));  // measured limit and margin: docs/sph.md
  n.velocity_gradient_correction = t.boolean_or("velocity_gradient_correction", false);
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
  return o;
}

}  // namespace

Scene read_scene(const toml::table& root, const std::string& source) {
  for (const auto& [key, node] : root) {
    const std::string_view name = key.str();
    if (name != "scene" && name != "initial" && name != "material" && name != "numerics" && name != "output")
      throw ParameterError(source + ": [" + std::string(name) +
                           "] is not a known table (allowed: scene, initial, material, numerics, output)");
  }
  if (!root.get("scene")) throw ParameterError(source + ": no [scene] table");
  if (!root.get("material")) throw ParameterError(source + ": no [material] table");

  const TableReader scene(section(root, source, "scene"), source, "scene");
  const TableReader material_table(section(root, source, "material"), source, "material");
  const TableReader initial(section(root, source, "initial"), source, "initial");
  const TableReader numerics(section(root, source, "numerics"), source, "numerics");
  const TableReader output(section(root, source, "output"), source, "output");

  const Geometry geometry = read_geometry(scene);
  const RestCriterion rest = read_rest(scene, geometry);
  Material material = read_material(material_table);
  const double base_stress = density(material) * geometry.gravity * (geometry.column_height + geometry.particle_spacing);
  if (!std::isfinite(base_stress))
    throw ParameterError(source + ": the weight of the column overflows: [material] density x [scene] gravity x "
                         "[scene] column_height is not a finite stress (Pa)");
  Scene result{source,
               {},
               geometry,
               read_initial(initial, material, geometry),
               read_numerics(numerics),
               read_output(output, geometry.end_time),
               std::move(material),
               rest,
               {scene.number_or("max_run_hours", 24.0, Range::positive(), "h")},
               {}};
  for (const TableReader* t : {&scene, &initial, &numerics, &output}) t->reject_unknown_keys();
  for (const TableReader* t : {&scene, &initial, &material_table, &numerics, &output})
    result.resolved.insert(t->table_name(), t->resolved());
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
