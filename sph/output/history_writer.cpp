#include "sph/output/history_writer.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>


namespace soilsph::sph {

namespace {
namespace fs = std::filesystem;

constexpr const char* kBoundaryHeader =
    "# soilsph boundary forces: the resultant force the soil exerts on each boundary (its ghost particles' pair "
    "terms of eq 12), N per metre of thickness (plane strain), in the scene's x and y axes\n"
    "# sampled inside the first step at or after each [output] history_interval, at its start t^n\n"
    "time_s,boundary,fx_N_per_m,fy_N_per_m\n";
constexpr const char* kGaugeHeader =
    "# soilsph gauges: position (m), displacement from t = 0 (m), velocity (m/s, at t^n) and p, q (Pa, "
    "compression-positive: p = -tr(sigma)/3, q = sqrt(3 J2)) at each gauge\n"
    "# sampled inside the first step at or after each [output] history_interval, at its start t^n\n"
    "time_s,gauge,x_m,y_m,ux_m,uy_m,vx_m_per_s,vy_m_per_s,p_Pa,q_Pa\n";

/// The shortest text that reads back to the same double ("nan" for NaN).
std::string number(double v) {
  if (std::isnan(v)) return "nan";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, end);
}

/// The lines of `file` that are comments, the column header, or rows whose time is below `time`;
/// empty if the file does not exist. `last` gets the latest time kept.
std::string rows_before(const fs::path& file, double time, double& last) {
  std::ifstream in(file);
  std::string kept, line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line.front() == '#' || !header) {
      header = header || line.front() != '#';
      kept += line + '\n';
      continue;
    }
    double t = 0.0;
    const auto [end, ec] = std::from_chars(line.data(), line.data() + line.size(), t);
    if (ec != std::errc() || *end != ',' || !(t < time)) continue;  // a torn last row, or after the checkpoint
    last = std::max(last, t);
    kept += line + '\n';
  }
  return kept;
}

void open(std::ofstream& out, const fs::path& file, const std::string& content) {
  out.open(file, std::ios::trunc);
  out << content;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + file.string());
}
}  // namespace

HistoryWriter::HistoryWriter(const fs::path& dir, std::vector<std::string> boundaries, std::vector<std::string> gauges)
    : HistoryWriter(dir, std::move(boundaries), std::move(gauges), -std::numeric_limits<double>::infinity()) {}

HistoryWriter HistoryWriter::continuing(const fs::path& dir, std::vector<std::string> boundaries,
                                        std::vector<std::string> gauges, double time) {
  return HistoryWriter(dir, std::move(boundaries), std::move(gauges), time);
}

HistoryWriter::HistoryWriter(const fs::path& dir, std::vector<std::string> boundaries, std::vector<std::string> gauges,
                             double keep_before)
    : dir_(dir), boundaries_(std::move(boundaries)), gauges_(std::move(gauges)) {
  fs::create_directories(dir_);
  const auto start = [&](std::ofstream& out, const char* name, const char* header) {
    std::string content = std::isfinite(keep_before) ? rows_before(dir_ / name, keep_before, last_sample_) : "";
    open(out, dir_ / name, content.empty() ? header : content);
  };
  start(forces_, kBoundaryFile, kBoundaryHeader);
  if (!gauges_.empty()) start(readings_, kGaugeFile, kGaugeHeader);
}

void HistoryWriter::write(double time, std::span<const Vec2> forces, std::span<const GaugeReading> readings) {
  const std::string t = number(time);
  std::string rows;
  for (std::size_t k = 0; k < boundaries_.size(); ++k)
    rows += t + ',' + boundaries_[k] + ',' + number(forces[k].x) + ',' + number(forces[k].y) + '\n';
  forces_ << rows << std::flush;
  if (!forces_) throw std::runtime_error("cannot write " + (dir_ / kBoundaryFile).string());
  if (gauges_.empty()) return;
  rows.clear();
  for (std::size_t k = 0; k < gauges_.size(); ++k) {
    const GaugeReading& r = readings[k];
    rows += t + ',' + gauges_[k];
    for (const double v : {r.position.x, r.position.y, r.displacement.x, r.displacement.y, r.velocity.x,
                           r.velocity.y, r.p, r.q})
      rows += ',' + number(v);
    rows += '\n';
  }
  readings_ << rows << std::flush;
  if (!readings_) throw std::runtime_error("cannot write " + (dir_ / kGaugeFile).string());
}

}  // namespace soilsph::sph
