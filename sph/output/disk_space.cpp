#include "sph/output/disk_space.h"

#include <sys/resource.h>
#include <sys/statvfs.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <system_error>

namespace soilsph::sph {

namespace {
std::string megabytes(std::uintmax_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  return text;
}
}  // namespace

void ensure_room(const std::filesystem::path& file, std::uintmax_t bytes) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::exists(file, error) ? std::filesystem::file_size(file, error) : 0;
  const std::filesystem::path folder = file.has_parent_path() ? file.parent_path() : ".";
  struct statvfs fs {};
  if (statvfs(folder.c_str(), &fs) == 0) {
    const std::uintmax_t free = static_cast<std::uintmax_t>(fs.f_bavail) * fs.f_frsize;
    if (free < bytes)
      throw std::runtime_error("no space left for " + file.string() + ": it needs about " + megabytes(bytes) +
                               " more, the disk has " + megabytes(free) + " free");
  }
  struct rlimit limit {};
  if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      size + bytes > static_cast<std::uintmax_t>(limit.rlim_cur))
    throw std::runtime_error(file.string() + " would grow past this process's file-size limit (ulimit -f) of " +
                             megabytes(limit.rlim_cur) + ": it needs about " + megabytes(size + bytes));
}

}  // namespace soilsph::sph
