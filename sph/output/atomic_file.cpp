#include "sph/output/atomic_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "sph/output/disk_space.h"

namespace soilsph::sph {

void replace_file(const std::filesystem::path& file, std::string_view content) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::filesystem::path temporary = file;
  temporary += ".tmp";
  ensure_room(temporary, content.size());
  errno = 0;
  {
    std::ofstream out(temporary);
    out << content;
    out.close();
    if (!out) {
      const std::string reason = errno ? std::strerror(errno) : "write failed";
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);  // the old file stays as it was, and no debris
      throw std::runtime_error("cannot write " + file.string() + ": " + reason);
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) throw std::runtime_error("cannot replace " + file.string() + ": " + error.message());
}

}  // namespace soilsph::sph
