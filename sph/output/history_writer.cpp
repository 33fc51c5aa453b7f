#include "sph/output/history_writer.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace soilsph::sph {

namespace {
namespace fs = std::filesystem;

constexpr const char* kSampling =
    "# sampled inside the first step at or after each [output] history_interval, at its start t^n\n";

std::string boundary_header(int dim) {
  if (dim == 2)
    return "# soilsph boundary forces: the resultant force the soil exerts on each boundary (its ghost particles' "
           "pair terms of eq 12), N per metre of thickness (plane strain), in the scene's x and y axes\n" +
           std::string(kSampling) + "time_s,boundary,fx_N_per_m,fy_N_per_m\n";
  return "# soilsph boundary forces: the resultant force the soil exerts on each boundary (its ghost particles' "
         "pair terms of eq 12), N, in the scene's x, y and z axes, on the part of the scene simulated (a symmetry "
         "plane carries the force of the mirrored part)\n" +
         std::string(kSampling) + "time_s,boundary,fx_N,fy_N,fz_N\n";
}

std::string gauge_header(int dim) {
  return "# soilsph gauges: position (m), displacement from t = 0 (m), velocity (m/s, at t^n) and p, q (Pa, "
         "compression-positive: p = -tr(sigma)/3, q = sqrt(3 J2)) at each gauge\n" +
         std::string(kSampling) +
         (dim == 2 ? "time_s,gauge,x_m,y_m,ux_m,uy_m,vx_m_per_s,vy_m_per_s,p_Pa,q_Pa\n"
                   : "time_s,gauge,x_m,y_m,z_m,ux_m,uy_m,uz_m,vx_m_per_s,vy_m_per_s,vz_m_per_s,p_Pa,q_Pa\n");
}

std::string energy_header(int dim, const std::string& scope) {
  const char* unit = dim == 2 ? "J_per_m" : "J";
  return "# soilsph energy of the soil, " + scope +
         ": kinetic E_k = sum 1/2 m |v|^2 (v at t^n, the mean of the leapfrog's half steps), gravitational "
         "potential relative to t = 0 E_p = -sum m g.(x - x0), and their sum, the mechanical energy\n" +
         std::string(kSampling) + "time_s,kinetic_" + unit + ",potential_" + unit + ",mechanical_" + unit + "\n";
}

/// The shortest text that reads back to the same double ("nan" for NaN).
std::string number(double v) {
  if (std::isnan(v)) return "nan";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, end);
}

void append_numbers(std::string& row, Vec2 v) { row += ',' + number(v.x) + ',' + number(v.y); }
void append_numbers(std::string& row, Vec3 v) { row += ',' + number(v.x) + ',' + number(v.y) + ',' + number(v.z); }

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
}  // namespace

HistoryFile::HistoryFile(fs::path path, const std::string& header, double keep_before) : path_(std::move(path)) {
  const std::string kept = std::isfinite(keep_before) ? rows_before(path_, keep_before, last_sample_) : "";
  out_.open(path_, std::ios::trunc);
  append(kept.empty() ? header : kept);
}

void HistoryFile::append(const std::string& rows) {
  out_ << rows << std::flush;
  if (!out_) throw std::runtime_error("cannot write " + path_.string());
}

template <int dim>
HistoryWriterOf<dim>::HistoryWriterOf(const fs::path& dir, std::vector<std::string> boundaries,
                                      std::vector<std::string> gauges, const std::string& energy_scope)
    : HistoryWriterOf(dir, std::move(boundaries), std::move(gauges), energy_scope,
                      -std::numeric_limits<double>::infinity()) {}

template <int dim>
HistoryWriterOf<dim> HistoryWriterOf<dim>::continuing(const fs::path& dir, std::vector<std::string> boundaries,
                                                      std::vector<std::string> gauges,
                                                      const std::string& energy_scope, double time) {
  return HistoryWriterOf(dir, std::move(boundaries), std::move(gauges), energy_scope, time);
}

namespace {
fs::path created(const fs::path& dir, const char* name) {
  fs::create_directories(dir);
  return dir / name;
}
}  // namespace

template <int dim>
HistoryWriterOf<dim>::HistoryWriterOf(const fs::path& dir, std::vector<std::string> boundaries,
                                      std::vector<std::string> gauges, const std::string& energy_scope,
                                      double keep_before)
    : boundaries_(std::move(boundaries)),
      gauges_(std::move(gauges)),
      forces_(created(dir, kBoundaryFile), boundary_header(dim), keep_before),
      energy_(dir / kEnergyFile, energy_header(dim, energy_scope), keep_before) {
  if (!gauges_.empty()) readings_.emplace(dir / kGaugeFile, gauge_header(dim), keep_before);
}

template <int dim>
void HistoryWriterOf<dim>::write(double time, std::span<const Vec<dim>> forces,
                                 std::span<const GaugeReadingOf<dim>> readings, const MechanicalEnergy& energy) {
  const std::string t = number(time);
  std::string rows;
  for (std::size_t k = 0; k < boundaries_.size(); ++k) {
    rows += t + ',' + boundaries_[k];
    append_numbers(rows, forces[k]);
    rows += '\n';
  }
  forces_.append(rows);
  if (readings_) {
    rows.clear();
    for (std::size_t k = 0; k < gauges_.size(); ++k) {
      const GaugeReadingOf<dim>& r = readings[k];
      rows += t + ',' + gauges_[k];
      append_numbers(rows, r.position);
      append_numbers(rows, r.displacement);
      append_numbers(rows, r.velocity);
      rows += ',' + number(r.p) + ',' + number(r.q) + '\n';
    }
    readings_->append(rows);
  }
  energy_.append(t + ',' + number(energy.kinetic) + ',' + number(energy.potential) + ',' +
                 number(energy.kinetic + energy.potential) + '\n');
}

template class HistoryWriterOf<2>;
template class HistoryWriterOf<3>;

}  // namespace soilsph::sph
