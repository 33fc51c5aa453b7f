#pragma once
/// @file
/// What every scene has, in two or three dimensions: [initial], [numerics], [output], the
/// materials, the rest criterion and the run limits of [scene], and the scene as read (`resolved`).
/// The 2D scene (sph/scene.h) and the 3D scene (sph/scene_3d.h) each add their geometry; both read
/// these parts with the same functions (sph/scene_sections.h). Keys: docs/reference/scenes.md.
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "sph/kernel.h"
#include "sph/output/frame.h"
#include "sph/rest.h"

namespace soilsph::sph {

/// [initial] stress: which free surface the geostatic stress hangs from (docs/reference/scenes.md).
enum class InitialStress {
  FlatSurface,     ///< "flat-surface": one level surface at the top of the soil's outline (the column's)
  LocalSurface,    ///< "local-surface": the top of the soil on the vertical through each particle
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

/// The largest δ × cfl [numerics] accepts for eq 11's density diffusion: alone, with Δt = cfl h/c,
/// it is stable to δ × cfl ≈ 0.30–0.35 on the lattice at h = 1.3Δp (stages/continuity.h).
inline constexpr double kLargestDiffusionTimesCfl = 0.25;

/// [numerics]
struct Numerics {
  double viscosity_alpha;  ///< α_Π, eq 37
  double viscosity_beta;   ///< β_Π, eq 37
  bool artificial_stress;  ///< Gray et al. 2001 on/off
  double artificial_stress_epsilon;
  double artificial_stress_exponent;
  double cfl;                         ///< Δt = cfl · h / (c + |v|max)
  bool velocity_gradient_correction;  ///< kernel-gradient correction of eq 23 (default off)
  double density_diffusion;           ///< δ of eq 11's diffusive term (stages/continuity.h; default 0, none)
  bool ghost_body_force;  ///< ghosts continue the soil's weight across their wall (stages/boundaries.h)
  KernelShape kernel;     ///< the smoothing kernel (sph/kernel.h; default the paper's cubic spline)
};

/// [output]
struct OutputSettings {
  double frame_interval;       ///< s between HDF5 frames
  double layer_thickness;      ///< m, thickness of the coloured horizontal layers
  FieldSet fields;             ///< fields written in every frame besides the positions (default: all)
  double checkpoint_interval;  ///< s of simulated time between checkpoints (DIR/checkpoint.h5)
  double history_interval;     ///< s between samples of boundary_forces.csv and gauges.csv; 0: none
  bool state_variables = false;  ///< UMAT plug-ins' STATEV in every frame (statev_1 …); listed when set
};

/// [scene] bounds on what a run may cost (sph/feasibility.h), for a user to lift deliberately.
struct RunLimits {
  double max_run_hours;  ///< estimated wall time to the end time
};

/// What a 2D and a 3D scene share.
struct SceneSettings {
  std::string source;                  ///< file name, for messages
  std::vector<std::string> overrides;  ///< the `--set section.key=value` applied, for messages
  InitialConditions initial;
  Numerics numerics;
  OutputSettings output;
  Material material;   ///< the first material in use: the only one of a single-material scene
  RestCriterion rest;  ///< [scene] stop_at_rest, rest_speed, rest_duration, rest_fraction
  RunLimits limits;    ///< [scene] max_run_hours
  /// The scene as read: every key with the value used, defaults included. Read back, it gives the
  /// same scene; a run saves it as DIR/scene.toml and records it in summary.json.
  toml::table resolved;
  /// The materials in use, in the order of their first use (materials[0] is `material`); the soil
  /// particles of each are contiguous, in this order (initial_state.h).
  std::vector<Material> materials;
  std::vector<std::string> material_names;  ///< their [materials.NAME] names ("" for [material])
  /// The table of material k, for messages: "[material]" or "[materials.NAME]".
  std::string material_table(std::size_t k) const {
    return material_names[k].empty() ? "[material]" : "[materials." + material_names[k] + "]";
  }
};

}  // namespace soilsph::sph
