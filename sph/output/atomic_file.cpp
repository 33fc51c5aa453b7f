#include "sph/output/atomic_file.h"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace soilsph::sph {

void replace_file(const std::filesystem::path& file, std::string_view content) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary);
    out << content;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw std::runtime_error("cannot replace " + file.string() + ": " + error.message());
}

}  // namespace soilsph::sph
