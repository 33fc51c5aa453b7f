#pragma once
/// @file
/// A collapse scene: geometry, initial state, material, numerics and output, read from a TOML file
/// with `--set section.key=value` overrides, every value validated (constitutive/parameters.h).
/// The keys and their meaning are listed in docs/reference/scenes.md.
#include <span>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "constitutive/parameters.h"
#include "sph/analysis/deposit.h"
#include "sph/analysis/gauges.h"
#include "sph/geometry/layout.h"
#include "sph/scene_settings.h"

namespace soilsph::sph {

/// What happens to the column's left wall: withdrawn at t = 0, kept, or lifted as a gate at a finite
/// speed (a moving wall: geometry/column.h).
enum class WallWithdrawal { Instant, None, Lift };

/// The soil's size, taken from the layout's regions: the column's W and H, and for [[regions]] the
/// same measures of whatever soil they hold.
struct SoilExtent {
  /// The soil's largest x (m): its outline's right edge less Δp/2, where a box's particle centres
  /// end (the column: W, its fixed wall). The deposit frame's default origin (read_measures.h).
  double largest_x;
  /// The height along −g from the lowest to the highest soil particle centre (m), at least Δp: the
  /// scale of the rest criterion's defaults, the deposit's toe thickness, the free-fall speed the
  /// soil must stay well below, the domain's headroom and gravity loading's measures.
  double height;
};

/// [scene]: geometry and duration. The soil and the walls are the layout (sph/geometry/layout.h,
/// docs/reference/scenes.md): from [[regions]] and [[boundaries]], or built from the column keys.
struct Geometry {
  bool column;              ///< the layout is the column shorthand's (column_width, ... given)
  double column_width;      ///< column only (0 for regions): W (m), the soil spans 0 ≤ x ≤ W
  double column_height;     ///< column only (0 for regions): H (m), the soil spans 0 ≤ y ≤ H
  SoilExtent soil_extent;   ///< the soil's size in every layout (the column: W and H)
  double particle_spacing;  ///< Δp (m), lattice spacing of soil and boundary particles
  double smoothing_ratio;   ///< h/Δp
  double end_time;          ///< s
  Vec2 gravity;             ///< m/s²; the scalar key g means (0, −g)
  WallWithdrawal wall_withdrawal;  ///< column only
  int boundary_layers;  ///< layers of ghost particles behind each wall
  double floor_length;  ///< column only: m, the floor extends from the fixed wall to x = W − floor_length
  double lift_speed;    ///< column only, wall_withdrawal = "lift": the gate's upward speed (m/s)
  Layout layout;        ///< regions, walls, lattice origin
  double surface_level;  ///< the geostatic free surface: the top of the soil's outline along −g (m)
  double base_level;     ///< the lowest soil particle along −g (m)

  double smoothing_length() const { return smoothing_ratio * particle_spacing; }
  double gravity_magnitude() const { return norm(gravity); }
  /// Unit vector along gravity; (0, −1) without gravity (heights and layers still need an "up").
  Vec2 down() const {
    const double g = gravity_magnitude();
    return g > 0.0 ? Vec2{gravity.x / g, gravity.y / g} : Vec2{0.0, -1.0};
  }
  /// Height of a point along −g (m): y when gravity is along −y.
  double height(Vec2 p) const {
    const Vec2 d = down();
    return -(d.x * p.x + d.y * p.y);
  }
};

/// The soil's height between its lowest and highest particle centres (m), at least Δp.
inline double soil_height(const Geometry& g) {
  return g.soil_extent.height;
}

/// What releases the column's soil and what it spreads on, [scene] keys shared by the 2D column and
/// the 3D slab: `wall_withdrawal` ("instant", "none" or "lift"), `lift_speed` (with "lift" only;
/// otherwise 0) and `floor_length` (default 6 W).
struct ColumnRelease {
  WallWithdrawal withdrawal;
  double lift_speed;    ///< m/s
  double floor_length;  ///< m
};
ColumnRelease read_column_release(const TableReader& t, double column_width);

/// A 2D (plane-strain) scene: what every scene has (SceneSettings) and the plane's geometry, the
/// materials of its regions, the deposit frame and the gauges.
struct Scene : SceneSettings {
  Geometry geometry;
  std::vector<int> region_material;  ///< each layout region's index into `materials`
  DepositFrame deposit;              ///< [deposit]: where the deposit measures are taken from
  std::vector<Gauge> gauges;         ///< [[gauges]]
};

/// Reads and validates a scene from a parsed TOML document; `source` names it in errors.
Scene read_scene(const toml::table& root, const std::string& source);
/// Parses `path`, applies the `section.key=value` overrides in order, then reads the scene.
Scene load_scene(const std::string& path, std::span<const std::string> overrides = {});
/// The same from TOML text (a checkpoint's scene); `source` names it in errors.
Scene parse_scene(const std::string& text, const std::string& source, std::span<const std::string> overrides = {});

/// The scene as run (Scene::resolved) as TOML text, which reads back to the same scene.
std::string scene_toml(const Scene& scene);
/// The same as a JSON object (summary.json's "inputs").
std::string scene_json(const Scene& scene);

}  // namespace soilsph::sph
