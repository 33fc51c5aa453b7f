#include "apps/soilsph/data_dir.h"

#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "constitutive/parameters.h"

namespace soilsph::cli {

namespace {
namespace fs = std::filesystem;

bool holds_data(const fs::path& dir) {
  std::error_code ignored;
  return fs::is_directory(dir / "data", ignored);
}

/// The folder of the running executable (Linux: /proc/self/exe), or nothing.
std::optional<fs::path> executable_dir() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (error) return std::nullopt;
  return exe.parent_path();
}

/// The source tree named by the build-tree marker beside the executable, or nothing.
std::optional<fs::path> source_tree(const fs::path& exe_dir) {
  std::ifstream marker(exe_dir / kBuildTreeMarker);
  std::string line;
  if (!marker || !std::getline(marker, line) || line.empty()) return std::nullopt;
  return fs::path(line);
}

fs::path find_data_dir() {
  if (const char* variable = std::getenv(kDataDirVariable); variable && *variable) {
    if (!holds_data(variable))
      throw ParameterError(std::string(kDataDirVariable) + "=" + variable +
                           ": no data/ folder there (it must name the folder holding data/, "
                           "verification/cases/ and scripts/, e.g. PREFIX/share/soilsph)");
    return variable;
  }
  std::vector<fs::path> tried;
  if (const std::optional<fs::path> exe_dir = executable_dir()) {
    const fs::path installed = *exe_dir / SOILSPH_DATA_FROM_BINDIR;
    if (holds_data(installed)) return installed.lexically_normal();
    tried.push_back(installed.lexically_normal());
    if (const std::optional<fs::path> source = source_tree(*exe_dir)) {
      if (holds_data(*source)) return *source;
      tried.push_back(*source);
    }
  }
  std::string places;
  for (const fs::path& p : tried) places += (places.empty() ? "" : ", ") + p.string();
  throw ParameterError(
      "cannot find soilsph's shipped files (data/, verification/cases/, scripts/); looked in " +
      (places.empty() ? std::string("no place (/proc/self/exe is unreadable)") : places) + ". Set " +
      kDataDirVariable + " to the folder that holds them");
}
}  // namespace

const fs::path& data_dir() {
  static const fs::path dir = find_data_dir();
  return dir;
}

}  // namespace soilsph::cli
