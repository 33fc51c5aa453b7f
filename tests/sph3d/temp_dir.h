#pragma once
// A directory of its own for each test, removed afterwards.
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <unistd.h>

namespace soilsph::test {

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("soilsph_" + name + "_" + std::to_string(::getpid()) +
                                                       "_" + std::to_string(std::random_device{}()))) {
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// Writes `text` to the file `name` in the directory and returns its path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return (path / name).string();
  }
};

}  // namespace soilsph::test
