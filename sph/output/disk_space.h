#pragma once
/// @file
/// Room for a write, checked before it starts: a write that fails half-way through an HDF5 file can
/// leave its metadata inconsistent and every earlier frame unreadable, so a frame or checkpoint that
/// would not fit is refused while the file is still intact.
#include <cstdint>
#include <filesystem>

namespace soilsph::sph {

/// Throws std::runtime_error with a one-line message if writing `bytes` more to `file` (which need
/// not exist yet) would exceed the free space of its file system or the process's file-size limit
/// (RLIMIT_FSIZE, e.g. `ulimit -f`).
void ensure_room(const std::filesystem::path& file, std::uintmax_t bytes);

}  // namespace soilsph::sph
