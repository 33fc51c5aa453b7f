#pragma once
/// @file
/// Where soilsph's shipped files are: the example scenes, materials and programmes (data/), the
/// verification cases (verification/cases/) and the plotting scripts (scripts/), laid out alike
/// under one folder in an install (PREFIX/share/soilsph) and in the source tree.
#include <filesystem>

namespace soilsph::cli {

/// The environment variable that names the folder, ahead of every other place.
inline constexpr const char* kDataDirVariable = "SOILSPH_DATA_DIR";

/// The file CMake writes beside the executable in the build tree, holding the source tree's path:
/// an executable run from where it was built finds the files there; an installed one has no such
/// file beside it.
inline constexpr const char* kBuildTreeMarker = "soilsph-source-dir.txt";

/// The folder holding data/, verification/cases/ and scripts/: $SOILSPH_DATA_DIR if set; else
/// ../share/soilsph from the executable's folder (an install: CMake's bin and share folders); else
/// the source tree the build-tree marker names. Throws ParameterError naming the places looked at if
/// none holds data/.
const std::filesystem::path& data_dir();

}  // namespace soilsph::cli
