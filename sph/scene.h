#pragma once
/// @file
/// A collapse scene: geometry, initial state, material, numerics and output, read from a TOML file
/// with `--set section.key=value` overrides, every value validated (constitutive/parameters.h).
/// The keys and their meaning are listed in docs/reference/scenes.md.
#include <span>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "sph/analysis/deposit.h"
#include "sph/analysis/gauges.h"
#include "sph/geometry/layout.h"
#include "sph/output/frame.h"
#include "sph/rest.h"

namespace soilsph::sph {

/// What happens to the column's left wall: withdrawn at t = 0, kept, or lifted as a gate at a finite
/// speed (a moving wall: geometry/column.h).
enum class WallWithdrawal { Instant, None, Lift };

/// [scene]: geometry and duration. The soil and the walls are the layout (sph/geometry/layout.h,
/// docs/reference/scenes.md): from [[regions]] and [[boundaries]], or built from the column keys.
struct Geometry {
  bool column;              ///< the layout is the column shorthand's (column_width, ... given)
  double column_width;      ///< column: W (m), the soil spans 0 ≤ x ≤ W; regions: the soil's largest x
                            ///< (the deposit measures' fixed-wall reference, analysis/deposit.h)
  double column_height;     ///< column: H (m), the soil spans 0 ≤ y ≤ H; regions: the soil's height
                            ///< along −g between its lowest and highest particles
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

/// [initial] stress: which free surface the geostatic stress hangs from (docs/reference/scenes.md).
enum class InitialStress {
  FlatSurface,   ///< "flat-surface": one level surface at the top of the soil's outline (the column's)
  LocalSurface,  ///< "local-surface": the top of the soil on the vertical through each particle
  GravityLoading,  ///< "gravity-loading": local-surface K0, then relaxed under gravity (gravity_loading.h)
};

/// [initial] gravity_loading_*: the relaxation of sph/gravity_loading.h.
struct GravityLoading {
  double damping = 0.0;            ///< share of the soil's velocity removed every step
  double kinetic_tolerance = 0.0;  ///< settled when kinetic energy / (M |g| H) is below it ...
  double stress_tolerance = 0.0;   ///< ... and max |Δσ_ij| per step / (ρ |g| H) too
  double max_time = 0.0;           ///< s of relaxation before it counts as not settling (an error)
};

/// [initial]: the geostatic state before the wall moves.
struct InitialConditions {
  double lateral_stress_ratio;     ///< K0 = σxx/σyy = σzz/σyy (of the first material in use)
  double overconsolidation_ratio;  ///< MCC: p_c = OCR × (p_c that puts the initial stress on the surface)
  double preconsolidation_floor;   ///< MCC: lower bound of the initial p_c (Pa), where p → 0
  /// K0 of each material in use (Scene::materials): the key if given, else each one's default.
  std::vector<double> material_lateral_stress_ratio;
  InitialStress stress = InitialStress::FlatSurface;  ///< the free surface σ_v is measured from
  GravityLoading gravity_loading{};                   ///< stress = "gravity-loading" only
};

/// [numerics]
struct Numerics {
  double viscosity_alpha;  ///< α_Π, eq 37
  double viscosity_beta;   ///< β_Π, eq 37
  bool artificial_stress;  ///< Gray et al. 2001 on/off
  double artificial_stress_epsilon;
  double artificial_stress_exponent;
  double cfl;                         ///< Δt = cfl · h / (c + |v|max)
  bool velocity_gradient_correction;  ///< kernel-gradient correction of eq 23 (default off)
  bool ghost_body_force;              ///< ghosts continue the soil's weight across their wall (stages/boundaries.h)
};

/// [output]
struct OutputSettings {
  double frame_interval;   ///< s between HDF5 frames
  double layer_thickness;  ///< m, thickness of the coloured horizontal layers
  FieldSet fields;         ///< fields written in every frame besides the positions (default: all)
  double checkpoint_interval;  ///< s of simulated time between checkpoints (DIR/checkpoint.h5)
  double history_interval;     ///< s between samples of boundary_forces.csv and gauges.csv; 0: none
};

/// [scene] bounds on what a run may cost (sph/feasibility.h), for a user to lift deliberately.
struct RunLimits {
  double max_run_hours;  ///< estimated wall time to the end time
};

struct Scene {
  std::string source;                  ///< file name, for messages
  std::vector<std::string> overrides;  ///< the `--set section.key=value` applied, for messages
  Geometry geometry;
  InitialConditions initial;
  Numerics numerics;
  OutputSettings output;
  Material material;  ///< the first material in use: the only one of a single-material scene
  RestCriterion rest;  ///< [scene] stop_at_rest, rest_speed, rest_duration, rest_fraction
  RunLimits limits;    ///< [scene] max_run_hours
  /// The scene as read: every key with the value used, defaults included. Read back (read_scene),
  /// it gives the same scene; a run saves it as DIR/scene.toml and records it in summary.json.
  toml::table resolved;
  /// The materials the regions use, in the order of their first use (materials[0] is `material`);
  /// the soil particles of each are contiguous, in this order (initial_state.h).
  std::vector<Material> materials;
  std::vector<std::string> material_names;  ///< their [materials.NAME] names ("" for [material])
  /// The table of material k, for messages: "[material]" or "[materials.NAME]".
  std::string material_table(std::size_t k) const {
    return material_names[k].empty() ? "[material]" : "[materials." + material_names[k] + "]";
  }
  std::vector<int> region_material;         ///< each layout region's index into `materials`
  DepositFrame deposit;       ///< [deposit]: where the deposit measures are taken from
  std::vector<Gauge> gauges;  ///< [[gauges]]
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
