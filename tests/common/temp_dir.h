#pragma once
// A fresh temporary directory per test, removed with everything in it when the test ends: made by
// mkdtemp(3), so two tests (or two builds testing at once) never share a name, as a fixed name under
// /tmp would.
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace soilsph::testing {

class TempDir {
 public:
  /// A new directory under the system's temporary directory whose name starts with `prefix`.
  explicit TempDir(const std::string& prefix = "soilsph-test") {
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// A path inside the directory.
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace soilsph::testing
