#pragma once
/// @file
/// Stop at rest: the run ends once the soil has come to rest, instead of integrating a deposit that
/// no longer changes up to a fixed end time.
///
/// Criterion: at least `fraction` of the soil particles move slower than `speed`, continuously for
/// `duration`. Not the largest speed alone: at the end of a collapse a few surface grains keep
/// rolling down the slope (2–3 of 2501 in the shipped MCC run, at 2–5.7 cm/s from t = 0.6 to
/// 0.75 s) while the deposit is at rest, and the largest speed would wait for them. A real slide
/// moves far more than 1 % of the particles (the thin D-P toe alone is several per cent), so a
/// fraction of 0.99 does not cut one off; the duration rules out the brief pauses of a flow. The
/// watch starts only once the soil has moved (more than the allowed movers faster than `speed`), so
/// a mass that never moves runs to the end time. Known limit: a failure that starts slowly, creeping
/// below `speed` for longer than `duration` after the first elastic jolt, is taken for rest
/// (measured: a 2 mm MCC column with p_c ≥ 1 kPa crept below 1 cm/s until 0.16 s, then ran out to
/// 8.2 cm; the run stopped at 0.084 s). For marginally stable scenes set a longer `rest_duration`
/// or stop_at_rest = false.
/// Defaults scale with the column: speed 1 % of the free-fall speed √(2 g H), duration √(H/g)
/// (1.08 cm/s and 0.078 s for the paper's 6 cm column). Keys: [scene] stop_at_rest, rest_speed,
/// rest_duration, rest_fraction (docs/method/sph.md).
#include <cmath>
#include <cstddef>

namespace soilsph::sph {

struct RestCriterion {
  bool enabled = true;
  double speed = 0.01;     ///< m/s
  double duration = 0.05;  ///< s
  double fraction = 0.99;  ///< of the soil particles

  /// The most particles that may still move faster than `speed` in a mass of `particles`.
  std::size_t movers_allowed(std::size_t particles) const {
    return static_cast<std::size_t>(std::floor((1.0 - fraction) * static_cast<double>(particles) + 1e-9));
  }
};

/// Tracks how long the criterion has held.
class RestWatch {
 public:
  /// What the watch remembers between steps (a checkpoint saves it).
  struct Memory {
    bool moved = false;   ///< the soil has moved: rest can be told from a start that is still slow
    double since = -1.0;  ///< time the criterion started to hold (< 0: it does not hold)
  };
  explicit RestWatch(const RestCriterion& criterion) : criterion_(criterion) {}
  RestWatch(const RestCriterion& criterion, Memory memory)
      : criterion_(criterion), moved_(memory.moved), since_(memory.since) {}
  Memory memory() const { return {moved_, since_}; }

  /// After the step that reached time t, with `moving` of `particles` faster than the rest speed;
  /// true once the soil has been at rest for the whole duration.
  bool at_rest(double t, std::size_t moving, std::size_t particles) {
    if (!criterion_.enabled) return false;
    if (moving > criterion_.movers_allowed(particles)) {
      moved_ = true;
      since_ = -1.0;
      return false;
    }
    if (!moved_) return false;
    if (since_ < 0.0) since_ = t;
    return t - since_ >= criterion_.duration;
  }

 private:
  RestCriterion criterion_;
  bool moved_ = false;   ///< the soil has moved: rest can be told from a start that is still slow
  double since_ = -1.0;  ///< time the criterion started to hold (< 0: it does not hold)
};

}  // namespace soilsph::sph
