// The range balancer on made-up costs per particle: its cuts converge to the split of equal cost,
// move little on one outlying step, keep every part measurable, cover the range, and start even
// when the thread count changes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <vector>

#include "sph/range_balancer.h"

using namespace soilsph::sph;

namespace {
/// Times each part of [0, cost.size()) as the sum of its particles' costs, `steps` times.
std::vector<double> run_steps(RangeBalancer& balance, const std::vector<double>& cost, int steps) {
  std::vector<double> seconds(static_cast<std::size_t>(balance.threads()));
  for (int s = 0; s < steps; ++s) {
    for (int t = 0; t < balance.threads(); ++t) {
      const auto [first, last] = balance.part(0, cost.size(), t);
      seconds[static_cast<std::size_t>(t)] = std::accumulate(cost.begin() + first, cost.begin() + last, 0.0);
      balance.record(t, seconds[static_cast<std::size_t>(t)]);
    }
    balance.rebalance();
  }
  return seconds;
}

/// The parts cover [begin, end) in thread order without gaps.
void check_cover(const RangeBalancer& balance, std::size_t begin, std::size_t end) {
  std::size_t next = begin;
  for (int t = 0; t < balance.threads(); ++t) {
    const auto [first, last] = balance.part(begin, end, t);
    CHECK(first == next);
    CHECK(last >= first);
    next = last;
  }
  CHECK(next == end);
}
}  // namespace

TEST_CASE("the balancer's cuts converge to equal cost", "[threads]") {
  // 1000 particles, the second half 4x as costly: total 2500, so two threads split at
  // 500 + 750/4 = 687.5 (cost 1250 each).
  std::vector<double> cost(1000, 1.0);
  std::fill(cost.begin() + 500, cost.end(), 4.0);
  RangeBalancer two;
  two.use_threads(2);
  CHECK(two.cuts()[1] == Approx(0.5));
  run_steps(two, cost, 40);
  CHECK(two.cuts()[1] == Approx(0.6875).margin(2e-3));
  check_cover(two, 0, cost.size());

  // Three threads on a linear ramp cost(x) = x: equal thirds of ∫x at x = N/√3 and N√(2/3).
  std::vector<double> ramp(3000);
  std::iota(ramp.begin(), ramp.end(), 0.5);
  RangeBalancer three;
  three.use_threads(3);
  const std::vector<double> seconds = run_steps(three, ramp, 60);
  CHECK(three.cuts()[1] == Approx(1.0 / std::sqrt(3.0)).margin(2e-3));
  CHECK(three.cuts()[2] == Approx(std::sqrt(2.0 / 3.0)).margin(2e-3));
  const double total = std::accumulate(ramp.begin(), ramp.end(), 0.0);
  for (double s : seconds) CHECK(s == Approx(total / 3).epsilon(0.01));
  check_cover(three, 100, 3100);
}

TEST_CASE("one step's outlying time moves a cut by at most kMaxMove", "[threads]") {
  // Even costs, then one step in which thread 0 took 100x as long (it lost its core): the
  // equal-cost cut would be near 0, halfway would move it by about a quarter of the range.
  RangeBalancer balance;
  balance.use_threads(2);
  balance.record(0, 100.0);
  balance.record(1, 1.0);
  balance.rebalance();
  CHECK(balance.cuts()[1] == Approx(0.5 - RangeBalancer::kMaxMove));
  // Back to a uniform cost (times in proportion to the parts): halfway back to the middle.
  const double cut = balance.cuts()[1];
  balance.record(0, cut);
  balance.record(1, 1.0 - cut);
  balance.rebalance();
  CHECK(balance.cuts()[1] == Approx(0.5 - RangeBalancer::kMaxMove / 2));
}

TEST_CASE("every part keeps a least share, and a new thread count starts even", "[threads]") {
  // All the cost in the first ten particles: the equal-cost cut would be at 0.5 %, below the
  // least share of an even part.
  std::vector<double> cost(1000, 0.0);
  std::fill(cost.begin(), cost.begin() + 10, 1.0);
  RangeBalancer balance;
  balance.use_threads(2);
  run_steps(balance, cost, 50);
  CHECK(balance.cuts()[1] == Approx(RangeBalancer::kMinShare / 2));
  check_cover(balance, 0, cost.size());

  balance.use_threads(2);  // same count: the cuts so far
  CHECK(balance.cuts()[1] == Approx(RangeBalancer::kMinShare / 2));
  balance.use_threads(1);  // one thread (a tuner's trial) needs no cuts: those of two are kept
  balance.rebalance();     // and a step that timed nothing moves nothing
  balance.use_threads(2);
  CHECK(balance.cuts()[1] == Approx(RangeBalancer::kMinShare / 2));
  balance.use_threads(4);
  REQUIRE(balance.cuts().size() == 5);
  for (std::size_t k = 0; k <= 4; ++k) CHECK(balance.cuts()[k] == Approx(k / 4.0));

  // No time measured (a region that did not run): the cuts stay.
  RangeBalancer idle;
  idle.use_threads(2);
  idle.rebalance();
  CHECK(idle.cuts()[1] == Approx(0.5));
}
