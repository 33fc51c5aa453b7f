#pragma once
/// @file
/// A one-line progress indicator (simulated time, steps, elapsed and remaining wall time) redrawn
/// in place on a terminal; silent when stderr is not a terminal, so logs and CI output stay clean.
#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

namespace soilsph::sph {

/// The progress line for simulated time `time` of `end_time` after `steps` steps and `elapsed_s`
/// seconds of wall time; the ETA extrapolates the wall time per simulated second so far.
std::string format_progress(double time, double end_time, std::size_t steps, double elapsed_s);

/// A one-line progress indicator on a terminal (isatty(stderr)), silent otherwise.
class Progress {
 public:
  /// Draws on std::cerr if stderr is a terminal, else stays silent.
  explicit Progress(double end_time);
  /// Draws on `out` if `enabled` (for tests and other streams).
  Progress(double end_time, std::ostream& out, bool enabled);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Redraws the line at most every `min_interval` of wall time (cheap to call every step).
  void update(double time, std::size_t steps);
  /// Draws the last state and ends the line; called by the destructor if not called before.
  void finish();

  /// Minimum wall time between redraws (default 0.2 s).
  std::chrono::duration<double> min_interval{0.2};

 private:
  void draw(double time, std::size_t steps);

  double end_time_;
  std::ostream* out_;
  bool enabled_, drawn_ = false, finished_ = false;
  double last_time_ = 0.0;
  std::size_t last_steps_ = 0;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace soilsph::sph
