#pragma once
/// @file
/// The run's time histories (docs/reference/output-formats.md): DIR/boundary_forces.csv, the force the soil
/// exerts on each boundary, and DIR/gauges.csv, what each gauge reads; one row per boundary (per
/// gauge) per sample, in long form (`pandas.read_csv(f, comment="#")` reads them). Rows are
/// flushed as they are written; a resumed run keeps the rows before its checkpoint's time.
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "sph/analysis/gauges.h"
#include "sph/geometry/vec2.h"

namespace soilsph::sph {

class HistoryWriter {
 public:
  /// New files in `dir` (earlier ones replaced): boundary_forces.csv with a row per name in
  /// `boundaries`, and gauges.csv if there are gauges.
  HistoryWriter(const std::filesystem::path& dir, std::vector<std::string> boundaries, std::vector<std::string> gauges);
  /// The files of a run resumed at `time`: rows of samples before `time` kept, later ones (written
  /// after the checkpoint) dropped. A file that is missing starts anew.
  static HistoryWriter continuing(const std::filesystem::path& dir, std::vector<std::string> boundaries,
                                  std::vector<std::string> gauges, double time);

  /// Time of the last sample in the files (after continuing()); negative if there is none.
  double last_sample() const { return last_sample_; }

  /// One sample: forces[k] for boundaries[k], readings[k] for gauges[k]. Throws std::runtime_error
  /// if a file cannot be written.
  void write(double time, std::span<const Vec2> forces, std::span<const GaugeReading> readings);

  static constexpr const char* kBoundaryFile = "boundary_forces.csv";
  static constexpr const char* kGaugeFile = "gauges.csv";

 private:
  HistoryWriter(const std::filesystem::path& dir, std::vector<std::string> boundaries, std::vector<std::string> gauges,
                double keep_before);
  std::filesystem::path dir_;
  std::vector<std::string> boundaries_, gauges_;
  std::ofstream forces_, readings_;
  double last_sample_ = -1.0;
};

}  // namespace soilsph::sph
