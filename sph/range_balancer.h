#pragma once
/// @file
/// Shares a loop over particles out among threads in parts of equal measured cost rather than
/// equal count.
///
/// Why: the cost of a particle is not uniform. MCC's stress update is elastic in the settled part of
/// the deposit and an implicit return with several Newton iterations where it yields; a free-surface
/// particle has fewer pairs than an interior one. With `schedule(static)` one thread waits at the
/// barrier for the other (measured on the shipped MCC scene: 2.4 s against 5.2 s of stress updates
/// per thread). A dynamic schedule would balance but costs an atomic per chunk and scatters the
/// particles that each thread's cache holds from the loops before.
///
/// How: each thread times its contiguous part of the loop in its own CPU time; between steps the
/// cuts move halfway towards those that would have given equal times if the cost per particle were
/// uniform within each thread's part, by at most kMaxMove of the range. The cost changes slowly (the
/// deposit moves little in one step), so the cuts follow it. CPU time and the bounded move keep a
/// busy machine from steering the cuts: with wall time, a step in which one thread lost its core
/// moved work to the other, and the cuts chased the other process (measured: auto threads with one
/// core busy, MCC to rest, 18.4 s median against 17.6 s unbalanced; 17.2 s with CPU time). Every
/// part keeps at least kMinShare of an even part, so no thread's time goes unmeasured. A change of
/// thread count starts again from an even split. Results do not depend on the cuts: every loop it
/// shares out writes per particle.
#include <time.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace soilsph::sph {

/// CPU time of the calling thread (s): what its work cost, without the time it waited for a core.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

class RangeBalancer {
 public:
  static constexpr double kMinShare = 0.1;  ///< of an even part
  /// The most a cut moves in one step, as a fraction of the range: one step in which a thread was
  /// descheduled (a busy machine) must not move the work far from the thread that waited.
  static constexpr double kMaxMove = 0.02;

  /// Sizes the balancer for `threads` (serial, before the parallel region): an even split if the
  /// count changed, the cuts so far otherwise. One thread needs no cuts: those of the last larger
  /// count are kept for when it returns (the thread tuner's trials of one thread).
  void use_threads(int threads) {
    if (threads <= 1) return;
    const auto n = static_cast<std::size_t>(threads);
    if (cuts_.size() == n + 1) return;
    cuts_.assign(n + 1, 0.0);
    for (std::size_t k = 0; k <= n; ++k) cuts_[k] = static_cast<double>(k) / static_cast<double>(n);
    seconds_.assign(n, 0.0);
    target_ = cuts_;
  }

  int threads() const { return static_cast<int>(seconds_.size()); }

  /// The part of [begin, end) that `thread` runs (parts are contiguous, in thread order, and cover
  /// the range). Reads only: any thread may call it while others do.
  std::pair<std::size_t, std::size_t> part(std::size_t begin, std::size_t end, int thread) const {
    const auto at = [&](std::size_t k) {
      return k + 1 == cuts_.size() ? end
                                   : begin + static_cast<std::size_t>(cuts_[k] * static_cast<double>(end - begin));
    };
    const auto t = static_cast<std::size_t>(thread);
    return {at(t), at(t + 1)};
  }

  /// `thread` took `seconds` for its part of this step (each thread writes its own slot).
  void record(int thread, double seconds) { seconds_[static_cast<std::size_t>(thread)] = seconds; }

  /// Moves the cuts halfway towards equal cost, by at most kMaxMove (serial, between steps), and
  /// forgets the times, so that a step that timed nothing (run on one thread) moves nothing.
  void rebalance() {
    const std::size_t n = seconds_.size();
    if (n < 2) return;
    double total = 0.0;
    for (double s : seconds_) total += s;
    if (!(total > 0.0)) return;
    // The cumulative cost is piecewise linear in the fraction, one piece per part; invert it at k/n.
    std::vector<double>& target = target_;
    std::size_t piece = 0;
    double before = 0.0;  // cost of the parts before `piece`
    for (std::size_t k = 1; k < n; ++k) {
      const double goal = total * static_cast<double>(k) / static_cast<double>(n);
      while (piece + 1 < n && before + seconds_[piece] < goal) before += seconds_[piece++];
      const double width = cuts_[piece + 1] - cuts_[piece];
      const double within = seconds_[piece] > 0.0 ? (goal - before) / seconds_[piece] : 0.5;
      target[k] = cuts_[piece] + std::clamp(within, 0.0, 1.0) * width;
    }
    const double least = kMinShare / static_cast<double>(n);
    for (std::size_t k = 1; k < n; ++k) {
      const double cut = cuts_[k] + std::clamp(0.5 * (target[k] - cuts_[k]), -kMaxMove, kMaxMove);
      // Room for the parts on either side: at least `least` each.
      cuts_[k] = std::clamp(cut, cuts_[k - 1] + least, 1.0 - static_cast<double>(n - k) * least);
    }
    std::fill(seconds_.begin(), seconds_.end(), 0.0);
  }

  /// The cut fractions: 0, the n − 1 inner cuts, 1.
  const std::vector<double>& cuts() const { return cuts_; }

 private:
  std::vector<double> cuts_{0.0, 1.0};
  std::vector<double> seconds_ = std::vector<double>(1, 0.0);
  std::vector<double> target_;  ///< the equal-cost cuts of the last times (scratch of rebalance)
};

}  // namespace soilsph::sph
