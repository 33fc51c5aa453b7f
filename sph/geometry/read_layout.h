#pragma once
/// @file
/// Reads [[regions]] and [[boundaries]] (docs/reference/scenes.md): every key validated, each error
/// naming the file, the table (e.g. "[[boundaries]] #2") and the key.
#include <string>
#include <utility>
#include <vector>
#include <toml++/toml.h>

#include "sph/geometry/layout.h"
#include "sph/geometry/vec3.h"

namespace soilsph {
class TableReader;
}

namespace soilsph::sph {

struct ReadLayout {
  Layout layout;
  toml::array regions, boundaries;  ///< as read, defaults resolved (the scene as run)
};

/// The regions and boundaries of `root` on the lattice of `spacing` from `origin`; a region's
/// `material` must be one of `materials` (its default: the only one).
ReadLayout read_layout(const toml::table& root, const std::string& source, double spacing, Vec2 origin,
                       const std::vector<std::string>& materials);

/// The boundaries alone (a column scene may add walls, e.g. a gate, to those of its shorthand).
toml::array read_boundaries(const toml::table& root, const std::string& source, std::vector<Wall>& walls);

/// How a [[boundaries]] wall acts on the soil, as its table gives it.
struct WallKindRead {
  WallKind kind;
  double friction_angle;  ///< degrees, Frictional only; otherwise 0
  bool symmetry_plane;    ///< kind = "symmetry"
};

/// `kind` ("free-slip", "no-slip", "frictional" or "symmetry") and, for "frictional",
/// `wall_friction_angle` (0 < δ < 90 degrees), recorded in `resolved` as written. A symmetry plane
/// is the mirror of a symmetric problem run in part: a free-slip wall (the same ghosts, the same
/// mirroring) that takes no friction angle and does not move (`velocity`, `start`, `end` or
/// `removed_at` with it is an error naming the file, the table and the key).
WallKindRead read_wall_kind(const TableReader& t, toml::table& resolved);

/// The tables of the array of tables `name` in `root` (empty if absent), each with its label
/// "name #k" for messages; throws ParameterError if `name` is not an array of tables.
std::vector<std::pair<const toml::table*, std::string>> tables_of(const toml::table& root, const std::string& source,
                                                                  std::string_view name);

/// An [x, y] pair (an [x, y, z] triple in space) of finite numbers (m or m/s) at `where`; throws
/// ParameterError otherwise.
template <int dim>
Vec<dim> read_vector_of(const toml::node& node, const std::string& where, std::string_view unit);
inline Vec2 read_vector(const toml::node& node, const std::string& where, std::string_view unit) {
  return read_vector_of<2>(node, where, unit);
}

/// The `points` of a table at `where`: at least `least` [x, y] points (m); throws ParameterError otherwise.
std::vector<Vec2> points_of(const toml::table& table, const std::string& where, std::size_t least);

/// A box side must fall on a cell edge of the lattice, origin + (i + ½)Δp along `axis`, so that the
/// box holds whole cells: its mass is then exactly ρ × its area (its volume in space). Throws
/// ParameterError naming `where`, `key` and the nearest cell edges otherwise.
void check_on_cell_edge(const std::string& where, std::string_view key, char axis, double value, double origin,
                        double dx);

/// The largest coordinate magnitude accepted (m): beyond it a scene is a typo.
inline constexpr double kLargestCoordinate = 1e4;

}  // namespace soilsph::sph
