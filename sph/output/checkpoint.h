#pragma once
/// @file
/// DIR/checkpoint.h5: everything a collapse needs to continue bit for bit (`soilsph collapse
/// --resume DIR`): every particle array, every soil state (stress, p_c, plastic strains), the loop
/// state (time, steps, Δt_{n−1}, c, the rest watch, the neighbour search's positions, the counts)
/// and the scene as run. The layout is in docs/reference/output-formats.md.
#include <filesystem>
#include <string>

#include "sph/particles.h"
#include "sph/solver.h"

namespace soilsph::sph {

struct Checkpoint {
  Particles particles;
  LoopState loop;
  std::string scene_toml;  ///< the scene as run (Scene::resolved as TOML text)
};

/// Writes `checkpoint` to FILE.tmp and renames it over FILE: a write that fails or is killed leaves
/// the previous checkpoint whole. Throws std::runtime_error (one line) on failure or lack of room.
void write_checkpoint(const std::filesystem::path& file, const Particles& particles, const LoopState& loop,
                      const std::string& scene_toml);

/// Reads a checkpoint; throws std::runtime_error naming the file if it is missing, unreadable or not
/// a soilsph checkpoint of this format.
Checkpoint read_checkpoint(const std::filesystem::path& file);

}  // namespace soilsph::sph
