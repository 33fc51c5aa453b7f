// The leapfrog with its half first kick and variable steps, the step clock, and the rest criterion.
#include <catch2/catch.hpp>

#include <cmath>

#include "helpers.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
/// One isolated soil particle under gravity: no neighbours, so a = −g exactly.
struct FreeFall {
  Particles p = test::lattice(1, 1e-3, 2000.0);
  LinearElastic model{{2000.0, 1.0e6, 0.3}};
  SolverSetup setup{.kernel = CubicSpline(1.3e-3),
                    .cfl = 0.5,
                    .sound_speed = 25.0,
                    .end_time = 1.0,
                    .frame_interval = 1.0,
                    .momentum = MomentumParams{},  // the artificial stress off
                    .guard = WallGuard{},
                    .walls = WallMotions{},
                    .rest = RestCriterion{},
                    .domain = Domain{}};
  FreeFall() {
    setup.momentum.gravity = {0.0, -9.81};
    setup.momentum.smoothing_length = 1.3e-3;
    p.y[0] = 1.0;
  }
};
}  // namespace

TEST_CASE("a step's acceleration has the artificial stress when, and only when, a particle is in tension",
          "[leapfrog]") {
  // The step skips the artificial-stress sum of every row when no particle is in tension (a flag
  // set while the stress is prepared, solver.h). Its a^n must equal the stages' own acceleration
  // (stages/momentum.h), which differs from the one without the term near a tensile particle.
  for (const double tension : {0.0, 200.0}) {  // Pa on the centre particle
    FreeFall f;
    f.p = test::lattice(7, 1e-3, 2000.0);
    f.setup.momentum.gravity = {0.0, 0.0};
    f.setup.momentum.artificial_stress = ArtificialStress(0.5, 2.55, f.setup.kernel, 1e-3);
    f.p.sxx[24] = tension;
    Particles expected = f.p, plain = f.p;
    NeighbourList nl;
    nl.build(expected.x, expected.y, f.setup.kernel);
    compute_artificial_stress(expected, 0.5);
    compute_acceleration(expected, nl, f.setup.momentum);
    MomentumParams without = f.setup.momentum;
    without.artificial_stress = ArtificialStress{};
    compute_acceleration(plain, nl, without);
    Workspace work(f.setup, f.p);
    advance(f.model, f.setup, f.p, work, 1e-6);
    double largest_term = 0.0;
    for (std::size_t i = 0; i < f.p.soil_count; ++i) {
      CHECK(f.p.ax[i] == Approx(expected.ax[i]).margin(1e-12));
      largest_term = std::max(largest_term, std::abs(expected.ax[i] - plain.ax[i]));
    }
    CAPTURE(tension);
    CHECK((largest_term > 1e-3) == (tension > 0.0));  // m/s²; T/ρ Δp ~ 100 m/s² on the tensile pair
  }
}

TEST_CASE("the leapfrog starts with half a kick: free fall is exact at whole steps", "[leapfrog]") {
  // With v^{1/2} = ½Δt a^0 the leapfrog reproduces y = y0 − ½ g t² exactly for a constant
  // acceleration, also across a change of step (kick ½(Δt_{n−1} + Δt_n)). A full first kick
  // (v^{1/2} = Δt a^0) would be ahead by ½ g Δt_0 t.
  FreeFall f;
  Workspace work(f.setup, f.p);
  double t = 0.0;
  for (const double dt : {1e-3, 1e-3, 2e-3, 0.5e-3, 3e-3, 1e-3}) {
    advance(f.model, f.setup, f.p, work, dt);
    t += dt;
  }
  CHECK(f.p.y[0] == Approx(1.0 - 0.5 * 9.81 * t * t).epsilon(1e-12));
  CHECK(f.p.x[0] == 0.0);
  // v^{n+½} = −g (t^n + ½Δt_n) with the last step's Δt = 1e-3.
  CHECK(f.p.vy[0] == Approx(-9.81 * (t - 0.5e-3)).epsilon(1e-12));
}

TEST_CASE("the step clock lands on the end time and calls frames within half a step", "[leapfrog]") {
  FreeFall f;
  f.setup.end_time = 0.1;
  f.setup.frame_interval = 0.03;
  StepClock clock(f.setup);
  std::vector<double> frames;
  double smallest = 1.0;
  const double cfl = 0.5 * 1.3e-3 / 7.0;  // 9.3e-5 s
  while (!clock.at_end()) {
    const double dt = clock.next_step(7.0, 0.0);
    smallest = std::min(smallest, dt);
    if (clock.step_taken()) frames.push_back(clock.time());
  }
  REQUIRE(frames.size() == 4);
  for (int k = 0; k < 3; ++k) CHECK(std::abs(frames[k] - 0.03 * (k + 1)) <= 0.5 * cfl * (1 + 1e-9));
  CHECK(frames[3] == 0.1);                    // the end time exactly
  CHECK(smallest >= 0.5 * cfl * (1 - 1e-9));  // never below half a CFL step
}

TEST_CASE("the output settings do not change the solution", "[leapfrog]") {
  // Frames every step or once: the same steps, the same final state, bit for bit.
  const auto final_x = [](double frame_interval) {
    const Scene scene =
        test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004", "scene.end_time=0.02",
                                            "output.frame_interval=" + std::to_string(frame_interval)});
    Particles p = build_particles(scene);
    set_geostatic_state(p, scene);
    const SolverSetup setup = make_solver_setup(scene);
    run(
        std::get<DruckerPrager>(scene.material), setup, p, [](const Particles&, double) {},
        [](double, std::size_t) {});
    return std::vector<double>(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(p.soil_count));
  };
  CHECK(final_x(0.02) == final_x(0.0001));
}

TEST_CASE("the CFL step falls with the flow speed", "[leapfrog]") {
  FreeFall f;
  StepClock clock(f.setup);
  CHECK(clock.next_step(25.0, 0.0) == Approx(0.5 * 1.3e-3 / 25.0));
  CHECK(clock.next_step(25.0, 25.0) == Approx(0.5 * 1.3e-3 / 50.0));
}

TEST_CASE("rest: a few movers are allowed, a sustained quiet is required", "[rest]") {
  RestCriterion c;
  c.speed = 0.01, c.duration = 0.05, c.fraction = 0.99;
  CHECK(c.movers_allowed(2501) == 25);  // floor(0.01 * 2501)
  CHECK(c.movers_allowed(100) == 1);
  RestWatch watch(c);
  CHECK_FALSE(watch.at_rest(0.01, 0, 2501));  // not yet moved: a slow start is not rest
  CHECK_FALSE(watch.at_rest(0.09, 0, 2501));
  CHECK_FALSE(watch.at_rest(0.10, 26, 2501));  // too many movers: the soil moves
  CHECK_FALSE(watch.at_rest(0.11, 3, 2501));   // quiet from 0.11 s ...
  CHECK_FALSE(watch.at_rest(0.155, 40, 2501));  // ... broken: starts again
  CHECK_FALSE(watch.at_rest(0.16, 0, 2501));
  CHECK_FALSE(watch.at_rest(0.2099, 0, 2501));
  CHECK(watch.at_rest(0.2101, 0, 2501));  // 0.05 s of quiet
  c.enabled = false;
  RestWatch off(c);
  CHECK_FALSE(off.at_rest(10.0, 0, 2501));
}

// The thresholds themselves, at times exact in binary (0.25, 1, 1.25 s) so that t − since equals the
// duration exactly: exactly the allowed number of movers is quiet (`moving > allowed` moves), and
// quiet for exactly the duration is rest (`>= duration`).
TEST_CASE("rest: exactly the allowed movers count as quiet, exactly the duration as rest", "[rest]") {
  RestCriterion c;
  c.speed = 0.01, c.duration = 0.25, c.fraction = 0.99;
  REQUIRE(c.movers_allowed(2501) == 25);
  SECTION("25 movers of 2501 start the quiet, and keep it") {
    RestWatch watch(c);
    CHECK_FALSE(watch.at_rest(0.5, 26, 2501));  // one more than allowed: moving
    CHECK_FALSE(watch.at_rest(1.0, 25, 2501));  // the allowed number: quiet starts at 1 s
    CHECK_FALSE(watch.at_rest(1.125, 25, 2501));
    CHECK(watch.at_rest(1.25, 25, 2501));  // 0.25 s later, every step with 25 movers: rest
  }
  SECTION("26 movers of 2501 restart the quiet") {
    RestWatch watch(c);
    CHECK_FALSE(watch.at_rest(0.5, 26, 2501));
    CHECK_FALSE(watch.at_rest(1.0, 0, 2501));
    CHECK_FALSE(watch.at_rest(1.125, 26, 2501));  // moves again: the quiet of 1 s is lost
    CHECK_FALSE(watch.at_rest(1.25, 0, 2501));    // quiet from 1.25 s
    CHECK_FALSE(watch.at_rest(1.375, 0, 2501));
    CHECK(watch.at_rest(1.5, 0, 2501));
  }
  SECTION("the allowed movers alone do not count as having moved") {
    RestWatch watch(c);
    for (const double t : {0.25, 0.5, 1.0, 2.0}) CHECK_FALSE(watch.at_rest(t, 25, 2501));
    CHECK_FALSE(watch.memory().moved);
    CHECK_FALSE(watch.at_rest(2.25, 26, 2501));
    CHECK(watch.memory().moved);
  }
  SECTION("quiet for a step less than the duration is not rest") {
    RestWatch watch(c);
    CHECK_FALSE(watch.at_rest(0.5, 26, 2501));
    CHECK_FALSE(watch.at_rest(1.0, 0, 2501));
    CHECK_FALSE(watch.at_rest(std::nextafter(1.25, 0.0), 0, 2501));  // an ulp short of 0.25 s
    CHECK(watch.at_rest(1.25, 0, 2501));
  }
  SECTION("a watch restored from a checkpoint's memory continues the quiet") {
    RestWatch watch(c, {.moved = true, .since = 1.0});
    CHECK(watch.at_rest(1.25, 0, 2501));
  }
}

TEST_CASE("stop at rest: a column that never moves runs to its end time", "[rest][column]") {
  const Scene scene = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004", "scene.wall_withdrawal=\"none\"",
                                                          "scene.rest_duration=0.02", "scene.end_time=0.05"});
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const SolverSetup setup = make_solver_setup(scene);
  const RunStatistics stats = run(
      std::get<DruckerPrager>(scene.material), setup, p, [](const Particles&, double) {},
      [](double, std::size_t) {});
  CHECK_FALSE(stats.stopped_at_rest);
  CHECK(stats.end_time == 0.05);
}

TEST_CASE("stop at rest: a collapse stops at rest before its end time, final frame at that time",
          "[rest][column]") {
  const Scene scene = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004"});
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const SolverSetup setup = make_solver_setup(scene);
  double last_frame = -1.0;
  const RunStatistics stats = run(
      std::get<DruckerPrager>(scene.material), setup, p, [&](const Particles&, double t) { last_frame = t; },
      [](double, std::size_t) {});
  CHECK(stats.stopped_at_rest);
  CHECK(stats.end_time < 0.6);  // the collapse is over by 0.4–0.5 s (docs/method/sph.md)
  CHECK(last_frame == stats.end_time);
}
