#pragma once
/// @file
/// A collapse scene: geometry, initial state, material, numerics and output, read from a TOML file
/// with `--set section.key=value` overrides, every value validated (constitutive/parameters.h).
/// The keys and their meaning are listed in docs/sph.md.
#include <span>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "sph/output/frame.h"
#include "sph/rest.h"

namespace soilsph::sph {

enum class WallWithdrawal { Instant, None };

/// [scene]: geometry and duration.
struct Geometry {
  double column_width;      ///< W (m): the soil spans 0 ≤ x ≤ W
  double column_height;     ///< H (m): the soil spans 0 ≤ y ≤ H
  double particle_spacing;  ///< Δp (m), lattice spacing of soil and boundary particles
  double smoothing_ratio;   ///< h/Δp
  double end_time;          ///< s
  double gravity;           ///< m/s², acting along −y
  WallWithdrawal wall_withdrawal;
  int boundary_layers;  ///< layers of ghost particles behind each wall
  double floor_length;  ///< m, the floor extends from the fixed wall to x = W − floor_length

  double smoothing_length() const { return smoothing_ratio * particle_spacing; }
};

/// [initial]: the geostatic state before the wall moves.
struct InitialConditions {
  double lateral_stress_ratio;     ///< K0 = σxx/σyy = σzz/σyy
  double overconsolidation_ratio;  ///< MCC: p_c = OCR × (p_c that puts the initial stress on the surface)
  double preconsolidation_floor;   ///< MCC: lower bound of the initial p_c (Pa), where p → 0
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
};

/// [output]
struct OutputSettings {
  double frame_interval;   ///< s between HDF5 frames
  double layer_thickness;  ///< m, thickness of the coloured horizontal layers
  FieldSet fields;         ///< fields written in every frame besides the positions (default: all)
  double checkpoint_interval;  ///< s of simulated time between checkpoints (DIR/checkpoint.h5)
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
  Material material;
  RestCriterion rest;  ///< [scene] stop_at_rest, rest_speed, rest_duration, rest_fraction
  RunLimits limits;    ///< [scene] max_run_hours
  /// The scene as read: every key with the value used, defaults included. Read back (read_scene),
  /// it gives the same scene; a run saves it as DIR/scene.toml and records it in summary.json.
  toml::table resolved;
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
