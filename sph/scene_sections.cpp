#include "sph/scene_sections.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "constitutive/material_limits.h"

namespace soilsph::sph::scene_sections {

const toml::table& section(const toml::table& root, const std::string& source, std::string_view name) {
  static const toml::table empty;
  const toml::node* node = root.get(name);
  if (!node) return empty;
  if (!node->is_table()) throw ParameterError(source + ": [" + std::string(name) + "] must be a table");
  return *node->as_table();
}

void check_tables(const toml::table& root, const std::string& source,
                  std::span<const std::string_view> allowed) {
  for (const auto& [key, node] : root) {
    const std::string_view name = key.str();
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    std::string list;
    for (const std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw ParameterError(source + ": [" + std::string(name) + "] is not a known table (allowed: " + list +
                         ")");
  }
}

int scene_dimension(const toml::table& root, const std::string& source) {
  const toml::node* scene = root.get("scene");
  if (!scene || !scene->is_table() || !scene->as_table()->get("dimension")) return 2;
  // A reader of its own: the scene's reader records the key (only where the file gives it).
  return static_cast<int>(TableReader(*scene->as_table(), source, "scene").integer_or("dimension", 2, 2, 3));
}

namespace {
MaterialTables material_tables(const toml::table& root, const std::string& source) {
  MaterialTables m;
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
    if (!node.is_table())
      throw ParameterError(source + ": [materials] " + name + " must be a table ([materials." + name + "])");
    m.names.push_back(name);
    m.tables.push_back(std::make_unique<TableReader>(*node.as_table(), source, "materials." + name));
  }
  return m;
}

/// The materials, once [scene] is known to be there (the first thing a scene file must have).
MaterialTables materials_of_scene(const toml::table& root, const std::string& source) {
  if (!root.get("scene")) throw ParameterError(source + ": no [scene] table");
  return material_tables(root, source);
}
}  // namespace

SceneTables::SceneTables(const toml::table& root_, const std::string& source_)
    : root(root_),
      source(source_),
      materials(materials_of_scene(root_, source_)),
      scene_table(section(root_, source_, "scene")),
      scene(scene_table, source_, "scene"),
      initial(section(root_, source_, "initial"), source_, "initial"),
      numerics(section(root_, source_, "numerics"), source_, "numerics"),
      output(section(root_, source_, "output"), source_, "output") {}

Resolution read_resolution(const TableReader& t, Range spacing_range) {
  Resolution r{};
  r.particle_spacing = t.number("particle_spacing", spacing_range, "m");
  r.smoothing_ratio = t.number("smoothing_ratio", Range::closed(1.0, 2.0));
  r.end_time = t.number("end_time", Range::positive(), "s");
  return r;
}

int read_boundary_layers(const TableReader& t, double smoothing_ratio) {
  // Enough layers to fill the support 2h of a soil particle sitting on the wall.
  const auto full_support = static_cast<long long>(std::ceil(2.0 * smoothing_ratio - 1e-9));
  return static_cast<int>(t.integer_or("boundary_layers", full_support, full_support, 10));
}

/// The lattice must fill the column exactly: a spacing that leaves a remainder builds a narrower or
/// lower column than the one described (0.003 m on 4 × 6 cm gave 3.9 cm, with the runout still
/// measured from 4 cm). The error names the nearest spacings that divide both sides.
void check_spacing_divides_column(const TableReader& t, double width, double height, double dx) {
  const auto divides = [](double length, double spacing) {
    const double n = length / spacing;
    return std::abs(n - std::round(n)) <= 1e-6 * n;
  };
  if (divides(width, dx) && divides(height, dx)) return;
  double below = 0.0, above = 0.0;  // the nearest spacings W/m that also divide H
  const double intervals = width / dx;
  for (double m = 1.0; m <= 4.0 * intervals + 4.0 && m <= 1e6; ++m) {
    const double s = width / m;
    if (!divides(height, s)) continue;
    if (s < dx && below == 0.0) below = s;
    if (s > dx) above = s;
  }
  std::ostringstream msg;
  msg << dx << " m does not divide the column (" << width << " m x " << height << " m is " << width / dx
      << " x " << height / dx << " spacings)";
  if (below > 0.0 || above > 0.0) {
    msg << "; the nearest spacings that do:";
    if (above > 0.0) msg << " " << above << " m";
    if (above > 0.0 && below > 0.0) msg << " and";
    if (below > 0.0) msg << " " << below << " m";
  }
  t.fail("particle_spacing", msg.str());
}

namespace {

/// Defaults scale with the column (sph/rest.h): 1 % of √(2gH) and √(H/g); without gravity the
/// run has no such scale and does not stop at rest unless asked to (then 1 cm/s and 0.1 s).
RestCriterion read_rest(const TableReader& t, double gravity, double height) {
  const bool falls = gravity > 0.0;
  RestCriterion r;
  r.enabled = t.boolean_or("stop_at_rest", falls);
  r.speed = t.number_or("rest_speed", falls ? 0.01 * std::sqrt(2.0 * gravity * height) : 0.01,
                        Range::positive(), "m/s");
  r.duration =
      t.number_or("rest_duration", falls ? std::sqrt(height / gravity) : 0.1, Range::positive(), "s");
  r.fraction = t.number_or("rest_fraction", 0.99, Range::open_closed(0.5, 1.0));
  return r;
}

/// The K0 a column may be given: below 1 (the active side) and at least the bound its yield surface
/// sets (0: none). A cone too slender for any K0 < 1 (cohesionless D-P with φ → 0) holds K0 = 1 alone.
Range lateral_stress_ratio_range(double bound) {
  if (!(bound > 0.0)) return Range::open(0.0, 1.0);
  return bound < 1.0 ? Range::closed_open(bound, 1.0) : Range::closed(1.0, 1.0);
}

InitialConditions read_initial(const TableReader& t, const std::vector<Material>& materials,
                               const std::vector<std::string>& names, const SoilColumn& soil) {
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
    const double nu = std::visit([](const auto& model) { return model.elasticity().poisson_ratio(); }, m);
    k0.push_back({nu / (1.0 - nu), soil.smallest_lateral_stress_ratio(m)});
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
        std::cerr << "note: " << t.source() << ": K0 of [materials." << names[k] << "] defaults to "
                  << k0[k].bound
                  << ", the smallest its yield surface holds at the soil's base (the elastic nu/(1-nu) = "
                  << k0[k].elastic << " lies outside it)\n";
      c.material_lateral_stress_ratio.push_back(k0[k].preferred());
    }
    c.lateral_stress_ratio = c.material_lateral_stress_ratio.front();
  }
  c.overconsolidation_ratio = t.number_or("overconsolidation_ratio", 1.0, Range::closed_open(1.0, 1e3));
  c.preconsolidation_floor = t.number_or("preconsolidation_floor", 100.0, limits::stress_range(), "Pa");
  const std::string stress =
      t.choice_or("stress", "flat-surface", {"flat-surface", "local-surface", "gravity-loading"});
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
    c.gravity_loading.stress_tolerance =
        t.number_or("gravity_loading_stress_change", 1e-5, Range::open(0.0, 1.0));
    c.gravity_loading.max_time =
        t.number_or("gravity_loading_max_time", 2.0, Range::open_closed(0.0, 100.0), "s");
  } else {
    for (const char* key : {"gravity_loading_damping", "gravity_loading_kinetic_energy",
                            "gravity_loading_stress_change", "gravity_loading_max_time"})
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
  n.artificial_stress_exponent = t.number_or("artificial_stress_exponent", 2.55, Range::closed(1.0, 10.0));
  n.cfl = t.number_or("cfl", 0.5, Range::open_closed(0.0, 2.0));  // limit and margin: docs/method/sph.md
  n.velocity_gradient_correction = t.boolean_or("velocity_gradient_correction", false);
  // δ of Molteni & Colagrossi (2009), 0.1 in DualSPHysics; the explicit diffusion is stable for
  // δ × cfl up to about 0.3 (stages/continuity.h).
  n.density_diffusion = t.number_or("density_diffusion", 0.0, Range::closed(0.0, 1.0));
  if (n.density_diffusion * n.cfl > kLargestDiffusionTimesCfl) {
    std::ostringstream msg;
    msg << "must be at most " << kLargestDiffusionTimesCfl << " / cfl = " << kLargestDiffusionTimesCfl / n.cfl
        << " (the density diffusion's stability with cfl = " << n.cfl << "), got " << n.density_diffusion;
    t.fail("density_diffusion", msg.str());
  }
  n.ghost_body_force = t.boolean_or("ghost_body_force", true);
  n.kernel = t.choice_or("kernel", "cubic-spline", {"cubic-spline", "wendland-c2"}) == "wendland-c2"
                 ? KernelShape::WendlandC2
                 : KernelShape::CubicSpline;
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
  o.history_interval =
      t.number_or("history_interval", 0.1 * o.frame_interval, Range::closed(0.0, end_time), "s");
  // Off unless asked for, and then listed in the scene as run (a scene without it reads as before).
  if (t.has("state_variables")) o.state_variables = t.boolean_or("state_variables", false);
  return o;
}

}  // namespace

SceneSettings read_settings(const SceneTables& t, std::span<const std::size_t> used, const SoilColumn& soil) {
  const RestCriterion rest = read_rest(t.scene, soil.gravity, soil.height);
  std::vector<Material> in_use;
  std::vector<std::string> names_in_use;
  double heaviest = 0.0;
  for (const std::size_t k : used) {
    in_use.push_back(read_material(*t.materials.tables[k]));
    names_in_use.push_back(t.materials.names[k]);
    heaviest = std::max(heaviest, density(in_use.back()));
  }
  const double base_stress = heaviest * soil.gravity * (soil.height + soil.spacing);
  if (!std::isfinite(base_stress))
    throw ParameterError(t.source +
                         ": the weight of the column overflows: [material] density x [scene] gravity x "
                         "[scene] column_height is not a finite stress (Pa)");
  InitialConditions initial = read_initial(t.initial, in_use, names_in_use, soil);
  Numerics numerics = read_numerics(t.numerics);
  OutputSettings output = read_output(t.output, soil.end_time);
  if (output.state_variables && std::none_of(in_use.begin(), in_use.end(), [](const Material& m) {
        return std::holds_alternative<UmatModel>(m);
      }))
    t.output.fail("state_variables",
                  "= true, but no material of the scene is a umat (only UMAT plug-ins have state variables)");
  const RunLimits limits{t.scene.number_or("max_run_hours", 24.0, Range::positive(), "h")};
  Material first = in_use.front();
  return SceneSettings{.source = t.source,
                       .overrides = {},
                       .initial = std::move(initial),
                       .numerics = numerics,
                       .output = output,
                       .material = std::move(first),
                       .rest = rest,
                       .limits = limits,
                       .resolved = {},
                       .materials = std::move(in_use),
                       .material_names = std::move(names_in_use)};
}

void reject_unknown_keys(const SceneTables& t) {
  for (const TableReader* r : {&t.scene, &t.initial, &t.numerics, &t.output}) r->reject_unknown_keys();
}

void check_unused_materials(const SceneTables& t, std::span<const std::size_t> used) {
  for (std::size_t k = 0; k < t.materials.tables.size(); ++k)
    if (std::find(used.begin(), used.end(), k) == used.end()) (void)read_material(*t.materials.tables[k]);
}

void record_settings(const SceneTables& t, const toml::table& scene_extra, toml::table& resolved) {
  toml::table scene_resolved = t.scene.resolved();
  for (const auto& [key, value] : scene_extra) scene_resolved.insert_or_assign(key, value);
  resolved.insert("scene", std::move(scene_resolved));
  for (const TableReader* r : {&t.initial, &t.numerics, &t.output})
    resolved.insert(r->table_name(), r->resolved());
  const MaterialTables& m = t.materials;
  if (m.names.front().empty()) {
    resolved.insert("material", m.tables.front()->resolved());
  } else {
    toml::table named;
    for (std::size_t k = 0; k < m.tables.size(); ++k) named.insert(m.names[k], m.tables[k]->resolved());
    resolved.insert("materials", std::move(named));
  }
}

toml::table parse_text(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ParameterError(source + ":" + std::to_string(e.source().begin.line) + ": " +
                         std::string(e.description()));
  }
}

}  // namespace soilsph::sph::scene_sections
