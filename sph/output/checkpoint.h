#pragma once
/// @file
/// DIR/checkpoint.h5: everything a collapse needs to continue bit for bit (`soilsph collapse
/// --resume DIR`): every particle array, every soil state (stress, p_c, plastic strains), the loop
/// state (time, steps, Δt_{n−1}, c, the rest watch, the neighbour search's positions, the counts)
/// and the scene as run. A run of either dimension: a 3D run's file adds the z arrays, the attribute
/// `dimension` = 3 and the dataset search_z to the plane's layout, which stays as it is. The layout
/// is in docs/reference/output-formats.md.
#include <filesystem>
#include <string>

#include "sph/particles.h"
#include "sph/solver.h"

namespace soilsph::sph {

template <int dim>
struct CheckpointOf {
  ParticlesOf<dim> particles;
  LoopState loop;
  std::string scene_toml;  ///< the scene as run (Scene::resolved or Scene3::resolved as TOML text)
};
using Checkpoint = CheckpointOf<2>;

/// Writes `checkpoint` to FILE.tmp and renames it over FILE: a write that fails or is killed leaves
/// the previous checkpoint whole. Throws std::runtime_error (one line) on failure or lack of room.
template <int dim>
void write_checkpoint(const std::filesystem::path& file, const ParticlesOf<dim>& particles, const LoopState& loop,
                      const std::string& scene_toml);

/// Reads a checkpoint of a run of dimension `dim`; throws std::runtime_error naming the file if it
/// is missing, unreadable, not a soilsph checkpoint of this format or of a run of the other dimension.
template <int dim = 2>
CheckpointOf<dim> read_checkpoint(const std::filesystem::path& file);

/// The scene a checkpoint saved (TOML text, which says its dimension), after the checks of
/// read_checkpoint but without reading the particles: what `--resume` reads to choose the dimension.
std::string read_checkpoint_scene(const std::filesystem::path& file);

}  // namespace soilsph::sph
