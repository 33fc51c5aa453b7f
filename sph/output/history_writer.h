#pragma once
/// @file
/// The run's time histories (docs/reference/output-formats.md): DIR/boundary_forces.csv, the force the soil
/// exerts on each boundary; DIR/gauges.csv, what each gauge reads; DIR/energy.csv, the soil's kinetic and
/// potential energy. One row per boundary (per gauge) per sample, in long form
/// (`pandas.read_csv(f, comment="#")` reads them). Rows are flushed as they are written; a resumed run
/// keeps the rows before its checkpoint's time. In space every vector has a z column, and forces and
/// energies are whole (N, J) instead of per metre of thickness.
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sph/analysis/energy.h"
#include "sph/analysis/gauges.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// One history file: its header, then rows appended and flushed as they come.
class HistoryFile {
 public:
  /// A new file at `path` with `header` (comment lines and the column line); or, if `keep_before`
  /// is finite, the file of a resumed run: its rows of samples before `keep_before` kept, later ones
  /// (written after the checkpoint) and a torn last row dropped. A file that is missing starts anew.
  HistoryFile(std::filesystem::path path, const std::string& header, double keep_before);
  /// Time of the last sample kept; negative if there is none.
  double last_sample() const { return last_sample_; }
  /// Appends `rows` (whole lines); throws std::runtime_error if the file cannot be written.
  void append(const std::string& rows);

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  double last_sample_ = -1.0;
};

template <int dim>
class HistoryWriterOf {
 public:
  /// New files in `dir` (earlier ones replaced): boundary_forces.csv with a row per name in
  /// `boundaries`, gauges.csv if there are gauges, and energy.csv, whose header says what part of the
  /// soil `energy_scope` is (e.g. "per metre of thickness (plane strain)").
  HistoryWriterOf(const std::filesystem::path& dir, std::vector<std::string> boundaries,
                  std::vector<std::string> gauges, const std::string& energy_scope);
  /// The files of a run resumed at `time`: rows of samples before `time` kept, later ones (written
  /// after the checkpoint) dropped. A file that is missing starts anew.
  static HistoryWriterOf continuing(const std::filesystem::path& dir, std::vector<std::string> boundaries,
                                    std::vector<std::string> gauges, const std::string& energy_scope,
                                    double time);

  /// Time of the last sample in the boundary file (after continuing()); negative if there is none.
  double last_sample() const { return forces_.last_sample(); }

  /// One sample: forces[k] for boundaries[k], readings[k] for gauges[k], the soil's energy.
  void write(double time, std::span<const Vec<dim>> forces, std::span<const GaugeReadingOf<dim>> readings,
             const MechanicalEnergy& energy);

  static constexpr const char* kBoundaryFile = "boundary_forces.csv";
  static constexpr const char* kGaugeFile = "gauges.csv";
  static constexpr const char* kEnergyFile = "energy.csv";

 private:
  HistoryWriterOf(const std::filesystem::path& dir, std::vector<std::string> boundaries,
                  std::vector<std::string> gauges, const std::string& energy_scope, double keep_before);
  std::vector<std::string> boundaries_, gauges_;
  HistoryFile forces_;
  std::optional<HistoryFile> readings_;
  HistoryFile energy_;
};
using HistoryWriter = HistoryWriterOf<2>;

}  // namespace soilsph::sph
