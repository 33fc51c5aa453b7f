// The thread tuner on made-up chunk timings: it keeps the faster count, follows a change of load,
// backs off its trials on a steady machine, and never changes an explicit count.
#include <catch2/catch.hpp>

#include "sph/thread_tuner.h"

using namespace soilsph::sph;

namespace {
/// Runs `chunks` chunks on a machine where one thread costs `one` and two cost `two` per
/// particle-step; returns how many chunks ran with two threads and how many were trials.
struct Tally {
  int with_two = 0, trials = 0;
};
Tally simulate(ThreadTuner& tuner, int chunks, double one, double two) {
  Tally t;
  for (int c = 0; c < chunks; ++c) {
    t.trials += tuner.trying();
    const int threads = tuner.threads();
    t.with_two += threads == 2;
    tuner.record((threads == 2 ? two : one) * 1000.0, 1000.0);
  }
  return t;
}
}  // namespace

TEST_CASE("the tuner keeps two threads on an idle machine and one on a busy one", "[threads]") {
  ThreadTuner tuner(2, true);
  CHECK(tuner.threads() == 2);
  // Idle: two threads 1.8x faster. Trials of one thread back off (2, 4, ..., 64 chunks apart):
  // 5 in the first 62 chunks, then one in 65, 12 in 500 chunks.
  Tally idle = simulate(tuner, 500, 1.0, 1.0 / 1.8);
  CHECK(idle.trials <= 12);
  CHECK(idle.with_two == 500 - idle.trials);
  // The machine gets busy: two threads at 0.55x. Within a few chunks the tuner runs one.
  simulate(tuner, 70, 1.0, 1.0 / 0.55);  // at most one back-off interval (64) to notice
  CHECK(tuner.threads() == 1);
  Tally busy = simulate(tuner, 500, 1.0, 1.0 / 0.55);
  CHECK(busy.with_two <= 10);  // only the trials
  // Idle again: back to two.
  simulate(tuner, 70, 1.0, 1.0 / 1.8);
  CHECK(simulate(tuner, 100, 1.0, 1.0 / 1.8).with_two >= 95);
}

TEST_CASE("noise within the switching margin does not flip the choice", "[threads]") {
  ThreadTuner tuner(2, true);
  const Tally t = simulate(tuner, 300, 1.0, 1.0 / 0.97);  // two threads 3 % slower: within the margin
  CHECK(t.with_two >= 290);
}

TEST_CASE("an explicit thread count is kept whatever the timings", "[threads]") {
  ThreadTuner fixed(2, false);
  CHECK(simulate(fixed, 100, 1.0, 10.0).with_two == 100);
  ThreadTuner single(1, true);  // nothing to choose from
  CHECK(simulate(single, 100, 1.0, 0.1).with_two == 0);
}
