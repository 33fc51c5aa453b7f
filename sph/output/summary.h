#pragma once
/// @file
/// summary.json: the figures of one SPH run. The field names are a contract with the scripts and
/// the documentation (docs/reference/output-formats.md lists them with their units).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "sph/geometry/layout.h"

namespace soilsph::sph {

/// summary.json's "initial_stress", in 2D and 3D runs alike: the [initial] stress method and, for
/// "gravity-loading", the relaxation's steps, kinetic energy / (M|g|H) and stress change per step /
/// (ρ|g|H) at its end.
struct InitialStressRecord {
  std::string method = "flat-surface";
  long long relaxation_steps = -1;  ///< < 0: no relaxation ran in this process (a resumed run)
  double relaxation_kinetic_energy = 0, relaxation_stress_change = 0;
  /// The field's JSON object; "" for "flat-surface", the default, whose runs have no such field (so
  /// that runs of scenes without the key keep their summary).
  std::string json() const;
};

/// What a run reports at its end; SI units, angles in degrees.
struct Summary {
  /// One of the scene's materials: its [materials.NAME] name ("" for [material]), model, integrator
  /// and soil particles; the frames' `material` field is its index in Summary::materials.
  struct Material {
    std::string name, model, integrator;
    std::size_t particles = 0;
  };
  std::string model, integrator;  ///< several materials: each distinct one, joined by " + "
  std::vector<Material> materials;
  std::size_t particles = 0, boundary_particles = 0, steps = 0;
  double end_time = 0, wall_seconds = 0, particle_steps_per_second = 0, runout_m = 0, height_m = 0,
         repose_angle_deg = 0, max_speed_end = 0, kinetic_energy_end = 0, particle_spacing = 0,
         smoothing_ratio = 0, time_step = 0, smallest_time_step = 0, largest_time_step = 0;
  int threads = 1;
  double runout_thick_m = 0;          ///< runout where the deposit is H0/10 thick (analysis/deposit.h)
  bool stopped_at_rest = false;       ///< the run ended at rest before the scene's end time
  std::size_t guard_corrections = 0;  ///< times the wall guard acted (0 in a sound run)
  std::size_t fallback_stress_updates =
      0;  ///< stress updates whose first attempt failed (split, substep or stress-free)
  /// The run reached its end time or rest; false while it runs and after a failure or a signal.
  bool complete = false;
  /// Why the run stopped: "end time", "at rest", "running" (written at the start: the record a
  /// killed run leaves), "signal SIGTERM", or the error that ended it.
  std::string stop_reason = "running";
  std::string version;       ///< soilsph version and git commit
  std::string command_line;  ///< as typed, shell-quoted
  std::string inputs_json;   ///< the scene as run (Scene::resolved) as a JSON object, or empty
  double resumed_from = -1;  ///< time of the checkpoint this run resumed from (s); < 0: none
  std::vector<Wall> boundaries;  ///< the scene's walls: label, kind, points and motion (pictures draw them)
  InitialStressRecord initial_stress;  ///< "initial_stress", unless "flat-surface"
};

/// Writes the summary as one JSON object (numbers in shortest round-trip form, non-finite
/// numbers as null); the file is replaced atomically. Throws std::runtime_error on I/O failure.
void write_summary_json(const std::filesystem::path& file, const Summary& summary);

/// The JSON text write_summary_json() writes (exposed for tests and for printing).
std::string summary_json(const Summary& summary);

}  // namespace soilsph::sph
