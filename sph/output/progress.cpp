// Progress: one line redrawn in place with a carriage return on a terminal, plain lines in a log.
#include "sph/output/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace soilsph::sph {
namespace {

/// Wall time as 42s, 3m07s or 1h02m.
std::string duration_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char text[32];
  if (s < 60) {
    std::snprintf(text, sizeof text, "%lds", s);
  } else if (s < 3600) {
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  }
  return text;
}

}  // namespace

std::string format_progress(double time, double end_time, std::size_t steps, double elapsed_s) {
  const double fraction = end_time > 0 ? std::clamp(time / end_time, 0.0, 1.0) : 1.0;
  // Remaining wall time at the mean wall time per simulated second so far (unknown before t > 0).
  const double eta = fraction > 0 ? elapsed_s * (1.0 - fraction) / fraction : -1.0;
  char text[160];
  std::snprintf(text, sizeof text, "t = %.4f / %.4f s (%3.0f%%)  steps %zu  elapsed %s  ETA %s", time,
                end_time, 100.0 * fraction, steps, duration_text(elapsed_s).c_str(),
                duration_text(eta).c_str());
  return text;
}

Progress::Progress(double end_time)
    : Progress(end_time, isatty(STDERR_FILENO) == 1 ? std::cerr : std::cout,
               isatty(STDERR_FILENO) == 1 ? Style::Terminal : Style::Log) {}

Progress::Progress(double end_time, std::ostream& out, Style style)
    : end_time_(end_time), out_(&out), style_(style), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  try {
    finish();
  } catch (...) {  // a destructor must not throw; the line is cosmetic
  }
}

void Progress::update(double time, std::size_t steps) {
  last_time_ = time;
  last_steps_ = steps;
  if (style_ == Style::Off || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  if (style_ == Style::Log) {
    const int tenths = end_time_ > 0 ? static_cast<int>(std::floor(10.0 * time / end_time_)) : 10;
    if (tenths <= logged_tenths_ && (drawn_ ? now - last_draw_ : now - start_) < log_interval) return;
    logged_tenths_ = std::max(logged_tenths_, tenths);
  } else if (drawn_ && now - last_draw_ < min_interval) {
    return;
  }
  draw(time, steps);
}

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (style_ != Style::Terminal) return;  // a log's last line is the run's own report
  draw(last_time_, last_steps_);
  *out_ << '\n' << std::flush;
}

void Progress::draw(double time, std::size_t steps) {
  last_draw_ = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(last_draw_ - start_).count();
  if (style_ == Style::Log) {
    *out_ << "progress: " << format_progress(time, end_time_, steps, elapsed) << std::endl;
  } else {
    // "\r" returns to the line start; "\033[K" clears what a longer previous line left behind.
    *out_ << '\r' << format_progress(time, end_time_, steps, elapsed) << "\033[K" << std::flush;
  }
  drawn_ = true;
}

}  // namespace soilsph::sph
