#pragma once
/// @file
/// Whole-file replacement that a concurrent reader never sees half-written.
#include <filesystem>
#include <string_view>

namespace soilsph::sph {

/// Writes `content` to FILE.tmp, then renames it over `file` (atomic on POSIX file systems);
/// creates the parent folder if needed. Throws std::runtime_error on any failure.
void replace_file(const std::filesystem::path& file, std::string_view content);

}  // namespace soilsph::sph
