#pragma once
/// @file
/// Chooses the thread count of the time loop while it runs, so that a second core helps on an idle
/// machine and costs nothing on a busy one, with no environment variable to set.
///
/// Why: a step is a few short loops separated by barriers. On an idle machine two threads run it
/// 1.75–1.85× faster than one; when another process holds a core, the two threads take turns on the
/// other and every barrier waits for a descheduled thread (measured: 0.74× of one thread with
/// OpenMP's default spinning waits, 0.88× with sleeping ones). No fixed setting wins in both cases,
/// and the load changes during a run. The results do not depend on the thread count (every loop
/// writes per particle), so the count can change between any two steps.
///
/// How: the run proceeds in chunks of steps, each one parallel region with the chosen count; the
/// tuner times every chunk per particle-step and now and then tries the other count for one chunk
/// (the candidates are the largest count and one thread), a quarter of the usual length, since on
/// a busy machine two threads with spinning waits can be 3–5× slower. It keeps whichever was
/// faster at its latest try. A try that confirms the current choice doubles the interval to the
/// next (up to `max_interval` chunks), so on a steady machine the trials cost about 1 % of the run;
/// a switch resets it, so a change of load is followed within a few chunks. Timing noise can make a
/// trial look faster than it is, which costs a few chunks on the slower count before the next trial
/// corrects it; on an idle machine auto matches two fixed threads in alternated runs, and on a busy
/// one it stays near one thread's time (measurements: docs/performance.md).
#include <algorithm>
#include <cstddef>

namespace soilsph::sph {

class ThreadTuner {
 public:
  /// `most` threads at most; `adaptive` false keeps `most` throughout (an explicit --threads N).
  ThreadTuner(int most, bool adaptive) : most_(std::max(1, most)), adaptive_(adaptive && most > 1) {}

  /// Thread count for the next chunk.
  int threads() const { return trying_ ? other() : current_; }
  /// The next chunk is a trial of the other count: keep it short, it may be much slower.
  bool trying() const { return trying_; }

  /// The chunk just run took `seconds` of wall time for `work` particle-steps.
  void record(double seconds, double work) {
    if (!adaptive_ || work <= 0.0) return;
    const double cost = seconds / work;
    if (!trying_) {
      cost_[slot(current_)] = cost;
      if (++since_trial_ >= interval_) trying_ = true, since_trial_ = 0;
      return;
    }
    trying_ = false;
    cost_[slot(other())] = cost;
    if (cost < kSwitchMargin * cost_[slot(current_)]) {  // the other count is faster now
      current_ = other();
      interval_ = kFirstInterval;
    } else {
      interval_ = std::min(2 * interval_, max_interval);
    }
  }

  /// Chunks between trials at most.
  std::size_t max_interval = 64;

 private:
  static constexpr std::size_t kFirstInterval = 2;
  /// A trial must be this much cheaper to switch: timing noise alone must not flip the choice.
  static constexpr double kSwitchMargin = 0.95;

  int other() const { return current_ == most_ ? 1 : most_; }
  int slot(int threads) const { return threads == most_ ? 0 : 1; }

  int most_;
  bool adaptive_;
  int current_ = most_;
  bool trying_ = false;
  std::size_t interval_ = kFirstInterval, since_trial_ = 0;
  double cost_[2] = {0.0, 0.0};  ///< seconds per particle-step with `most_` threads and with one
};

}  // namespace soilsph::sph
