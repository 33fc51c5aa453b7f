#pragma once
/// @file
/// A 3D scene (`[scene] dimension = 3`): what every scene has (SceneSettings: materials,
/// [initial], [numerics], [output], rest, limits, `resolved`) and the geometry of space, built from
/// one of two shorthands or from [[regions]] (docs/reference/scenes.md, "Three dimensions"):
/// - the axisymmetric column, column_radius and column_height: a cylinder of soil standing free on
///   a no-slip floor, axis along y through x = z = 0, run as a quarter (default), a half or whole;
/// - the slab, column_width, column_height and slab_thickness: the 2D column extruded along z
///   between two free-slip planes, with the 2D column's fixed wall, floor and withdrawal;
/// - [[regions]] (sph/read_regions_3d.h): boxes, cylinders, extrusions, STL solids and imported
///   particles, each of its [materials.NAME], standing on a no-slip floor.
/// Any scene may add the planar walls of its [[boundaries]] (sph/read_boundaries_3d.h).
/// y is up, as in 2D: gravity defaults to (0, −9.81, 0).
#include <span>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "sph/analysis/axisymmetric_deposit.h"
#include "sph/geometry/cylinder.h"
#include "sph/geometry/extrusion.h"
#include "sph/geometry/planar_wall.h"
#include "sph/geometry/regions_3d.h"
#include "sph/geometry/solid.h"
#include "sph/geometry/vec3.h"
#include "sph/geometry/wall_motion.h"
#include "sph/scene.h"
#include "sph/scene_settings.h"

namespace soilsph::sph {

/// A wall of space: its plane polygon, how it acts on the soil and moves (as the 2D Wall) and its
/// name in the run's histories.
struct Wall3 {
  PlanarWall plane;
  WallKind kind = WallKind::FreeSlip;
  double friction_angle = 0.0;  ///< degrees, Frictional only
  /// kind = "symmetry" (free slip, still, normal to an axis): its ghosts are the soil's mirror
  /// images (stages/mirror_images.h), not lattice ghosts
  bool symmetry_plane = false;
  /// "floor", "symmetry_x", "symmetry_z", "symmetry_far", "fixed_wall", "removable_wall"; a
  /// [[boundaries]] name ("boundary_K" by default)
  std::string label;
  WallMotionOf<3> motion;  ///< still unless it moves or is removed (the slab's gate, [[boundaries]])
};

/// [scene] of a 3D scene: the shorthand's keys and what they build.
struct Geometry3 {
  enum class Shape { AxisymmetricColumn, Slab, Regions };
  Shape shape;

  // The keys (each as used; those of the other shorthand, and all of them with [[regions]], 0).
  double column_radius;            ///< axisymmetric: r0 (m)
  double column_width;             ///< slab: W (m), soil on 0 ≤ x ≤ W
  double column_height;            ///< H0 (m), soil on 0 ≤ y ≤ H0
  double slab_thickness;           ///< slab: T (m), soil on 0 < z < T
  ColumnSymmetry symmetry;         ///< axisymmetric; the slab: None
  double floor_radius;             ///< axisymmetric: half-width of the square floor (m)
  double floor_length;             ///< slab: the floor from the fixed wall towards −x (m)
  WallWithdrawal wall_withdrawal;  ///< slab: "instant", "none" or "lift"; axisymmetric: None (no wall)
  double lift_speed;               ///< slab, "lift": the gate's upward speed (m/s); otherwise 0
  double particle_spacing;         ///< Δp (m)
  double smoothing_ratio;          ///< h/Δp
  double end_time;                 ///< s
  Vec3 gravity;                    ///< m/s²; the scalar key g means (0, −g, 0)
  int boundary_layers;             ///< layers of ghost particles behind each wall

  // What they build.
  /// The soil: the shorthand's one region (its cylinder or extruded column), or the [[regions]].
  std::vector<SoilRegion3> regions;
  Lattice3 lattice;  ///< soil and ghost nodes (axisymmetric: origin (Δp/2, Δp/2, Δp/2); slab: (0, 0, Δp/2);
                     ///< regions: [scene] lattice_origin, default (Δp/2, Δp/2, Δp/2))
  std::vector<Wall3> walls;  ///< every wall present at t = 0, the shape's then the [[boundaries]] (a wall
                             ///< withdrawn at t = 0 is never built)
  /// The walls withdrawn at t = 0 (the slab's removable wall with "instant", [[boundaries]] with
  /// removed_at = 0): never built for the run; they hold the soil while [initial] "gravity-loading"
  /// relaxes it before t = 0 (sph/gravity_loading.h), as a 2D scene's do.
  std::vector<Wall3> withdrawn_walls;
  Box3 domain;               ///< no soil particle may leave it: the floor's extent, ghosts and kernel support
                             ///< around it, up to twice the soil's height above the floor
  double floor_level;        ///< the floor surface's height y (m): the potential-energy datum; the
                             ///< column's 0, the slab's −Δp/2 (regions: [scene] floor_level)
  double surface_level;      ///< the geostatic free surface (m): the column's H0, the slab's
                             ///< H0 + Δp/2 (regions: their top)
  double base_level;         ///< the lowest soil row (m): the column's Δp/2, the slab's 0 (regions:
                             ///< the lowest soil row)
  DepositAxis deposit_axis;  ///< the column's axis on the floor (the slab: the fixed wall's foot, up y;
                             ///< regions: [deposit] axis)
  double azimuth_span_deg;   ///< 90, 180 or 360 (the slab: 0, no azimuths; regions: [deposit] azimuth_span)
  bool deposit_measured = true;  ///< false for regions without [deposit]: their measures are null

  double smoothing_length() const { return smoothing_ratio * particle_spacing; }
  double gravity_magnitude() const { return norm(gravity); }
  /// Unit vector along gravity; (0, −1, 0) without gravity.
  Vec3 down() const {
    const double g = gravity_magnitude();
    return g > 0.0 ? (1.0 / g) * gravity : Vec3{0.0, -1.0, 0.0};
  }
  /// Height of a point along −g (m): y when gravity is along −y.
  double height(Vec3 p) const { return -dot(down(), p); }
};

/// The soil's height between its lowest and highest particle centres (m), at least Δp (as the 2D
/// SoilExtent::height): column_height, which [[regions]] set so.
inline double soil_height(const Geometry3& g) {
  return g.column_height;
}

/// A 3D scene.
struct Scene3 : SceneSettings {
  Geometry3 geometry;
  std::vector<GaugeOf<3>> gauges;  ///< [[gauges]], positions [x, y, z]
  std::vector<int> region_material;  ///< each region's index into `materials` (the shorthands: {0})
};

/// The scene of a dimension: Scene in the plane, Scene3 in space.
template <int dim>
using SceneOf = std::conditional_t<dim == 2, Scene, Scene3>;

/// The box of the floor's extent [x_lo, x_hi] × [z_lo, z_hi] grown by the ghost layers and the
/// kernel support, from below the floor's ghosts up to twice the soil's height above the floor (or
/// the walls' tops, if higher): Geometry3::domain.
Box3 domain_around(const Geometry3& g, double x_lo, double x_hi, double z_lo, double z_hi, double wall_top);

/// The default floor half-width of an axisymmetric column: twice the runout of Lube et al. (2004)
/// at its aspect ratio beyond the column, plus four spacings: r0 (1 + 2 (r∞ − r0)/r0) + 4 Δp.
double default_floor_radius(double column_radius, double column_height, double spacing);

/// Reads and validates a 3D scene from a parsed TOML document; `source` names it in errors. Throws
/// ParameterError for a 2D scene (no `dimension` or dimension = 2).
Scene3 read_scene_3d(const toml::table& root, const std::string& source);
/// Parses `path`, applies the `section.key=value` overrides in order, then reads the 3D scene.
Scene3 load_scene_3d(const std::string& path, std::span<const std::string> overrides = {});
/// The same from TOML text (a checkpoint's scene).
Scene3 parse_scene_3d(const std::string& text, const std::string& source,
                      std::span<const std::string> overrides = {});

/// A scene of either dimension, read after the overrides (which may set scene.dimension): a Scene
/// (2D) for dimension 2 or none, a Scene3 for 3.
using AnyScene = std::variant<Scene, Scene3>;
AnyScene load_any_scene(const std::string& path, std::span<const std::string> overrides = {});
AnyScene parse_any_scene(const std::string& text, const std::string& source,
                         std::span<const std::string> overrides = {});

/// The scene as run (Scene3::resolved) as TOML text, which reads back to the same scene.
std::string scene_toml(const Scene3& scene);
/// The same as a JSON object (summary.json's "inputs").
std::string scene_json(const Scene3& scene);

}  // namespace soilsph::sph
