#pragma once
/// @file
/// The readers of the parts of a scene file that 2D and 3D scenes share (SceneSettings): the
/// materials, [initial], [numerics], [output], and the rest, limit and resolution keys of [scene];
/// plus the overrides and the dimension check. sph/scene.cpp and sph/scene_3d.cpp read their own
/// geometry and call these for the rest, so both kinds of scene validate and record these keys alike.
#include <toml++/toml.h>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "constitutive/parameters.h"
#include "sph/scene_settings.h"

namespace soilsph::sph::scene_sections {

/// The table `name` of `root`, or an empty one if absent; throws if it is not a table.
const toml::table& section(const toml::table& root, const std::string& source, std::string_view name);

/// Throws for a top-level table of `root` not in `allowed` (the message lists them).
void check_tables(const toml::table& root, const std::string& source,
                  std::span<const std::string_view> allowed);

/// [scene] dimension: 2 if absent, else 2 or 3 (an error naming the file, the key and the values).
int scene_dimension(const toml::table& root, const std::string& source);

/// The named materials of [materials.NAME] (or the one [material], named "").
struct MaterialTables {
  std::vector<std::string> names;
  std::vector<std::unique_ptr<TableReader>> tables;
};

/// A scene file's shared tables, each with the reader that validates it and records what it read.
/// Throws if [scene] is missing or the materials are neither one [material] nor [materials.NAME].
struct SceneTables {
  SceneTables(const toml::table& root, const std::string& source);

  const toml::table& root;
  std::string source;
  MaterialTables materials;
  const toml::table& scene_table;
  TableReader scene, initial, numerics, output;
};

/// [scene] particle_spacing (in `spacing_range`), smoothing_ratio, end_time.
struct Resolution {
  double particle_spacing;
  double smoothing_ratio;
  double end_time;
};
Resolution read_resolution(const TableReader& t, Range spacing_range);

/// [scene] boundary_layers: default and least the layers that fill the support 2h of a soil
/// particle sitting on a wall, at most 10.
int read_boundary_layers(const TableReader& t, double smoothing_ratio);

/// The column's lattice must fill its width and height exactly; else an error naming
/// particle_spacing and the nearest spacings that divide both.
void check_spacing_divides_column(const TableReader& t, double width, double height, double spacing);

/// K0's default (ν/(1−ν)) and its lower bound (the yield surface's) for one material.
struct LateralStressRatio {
  double elastic, bound;
  double preferred() const { return std::max(elastic, bound); }
};

/// What the shared readers need of the soil's geometry.
struct SoilColumn {
  double gravity;   ///< |g| (m/s²)
  double height;    ///< the soil's height along −g (m): the rest criterion's scales
  double spacing;   ///< Δp (m): the weight check takes height + Δp
  double end_time;  ///< s: bounds [output] frame_interval and history_interval
  /// The smallest admissible K0 of a material at the soil's base (initial_state.h).
  std::function<double(const Material&)> smallest_lateral_stress_ratio;
};

/// Reads, in order, the rest criterion of [scene], the materials `used` (indices into
/// t.materials), the weight check, [initial], [numerics], [output] and [scene] max_run_hours.
SceneSettings read_settings(const SceneTables& t, std::span<const std::size_t> used, const SoilColumn& soil);

/// Throws for any key of [scene], [initial], [numerics], [output] neither read nor accepted.
void reject_unknown_keys(const SceneTables& t);

/// Reads (validates) every material table not in `used`, so that a typo in one is never silent.
void check_unused_materials(const SceneTables& t, std::span<const std::size_t> used);

/// Adds [scene] (with `scene_extra`'s keys, which the geometry read without its TableReader),
/// [initial], [numerics], [output] and the material table(s) as read to `resolved`.
void record_settings(const SceneTables& t, const toml::table& scene_extra, toml::table& resolved);

/// Parses TOML text; a syntax error becomes a ParameterError naming `source` and the line.
toml::table parse_text(const std::string& text, const std::string& source);

/// Applies the overrides to `root`, reads it with `read(root)` (errors note the overrides) and
/// records the overrides in the scene.
template <class Read>
auto read_overridden(toml::table& root, std::span<const std::string> overrides, Read&& read) {
  for (const std::string& assignment : overrides) apply_override(root, assignment);
  auto scene = blaming_overrides(overrides, [&] { return read(root); });
  scene.overrides.assign(overrides.begin(), overrides.end());
  return scene;
}

}  // namespace soilsph::sph::scene_sections
