#pragma once
/// @file
/// A one-line progress indicator (simulated time, steps, elapsed and remaining wall time) redrawn
/// in place on a terminal; in a log (stderr not a terminal) a plain line on stdout at every tenth of
/// the run and at least every minute, so that a batch job's log shows it is alive and when it ends.
#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

namespace soilsph::sph {

/// The progress line for simulated time `time` of `end_time` after `steps` steps and `elapsed_s`
/// seconds of wall time; the ETA extrapolates the wall time per simulated second so far.
std::string format_progress(double time, double end_time, std::size_t steps, double elapsed_s);

class Progress {
 public:
  enum class Style {
    Terminal,  ///< one line redrawn in place
    Log,       ///< a plain line at every tenth of the run and at least every `log_interval`
    Off,
  };
  /// Terminal on std::cerr if stderr is a terminal, else Log on std::cout.
  explicit Progress(double end_time);
  /// Draws on `out` in `style` (for tests and other streams).
  Progress(double end_time, std::ostream& out, Style style);
  /// Terminal if `enabled`, else Off.
  Progress(double end_time, std::ostream& out, bool enabled)
      : Progress(end_time, out, enabled ? Style::Terminal : Style::Off) {}
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// Redraws the line at most every `min_interval` of wall time (cheap to call every step).
  void update(double time, std::size_t steps);
  /// Draws the last state and ends the line; called by the destructor if not called before.
  void finish();

  /// Minimum wall time between redraws (default 0.2 s).
  std::chrono::duration<double> min_interval{0.2};
  /// Longest wall time between two log lines (default 60 s).
  std::chrono::duration<double> log_interval{60.0};

 private:
  void draw(double time, std::size_t steps);

  double end_time_;
  std::ostream* out_;
  Style style_;
  bool drawn_ = false, finished_ = false;
  int logged_tenths_ = 0;  ///< tenths of the run already logged
  double last_time_ = 0.0;
  std::size_t last_steps_ = 0;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace soilsph::sph
