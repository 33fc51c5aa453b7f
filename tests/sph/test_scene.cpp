// Scene input: the shipped scenes, overrides, validation messages, the initial geostatic state.
#include <catch2/catch.hpp>

#include "helpers.h"
#include "sph/frame_buffers.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

TEST_CASE("the shipped scenes hold the paper's column: 41 x 61 = 2501 particles at 1 mm", "[scene]") {
  for (const char* name : {"collapse-dp", "collapse-mcc"}) {
    const Scene scene = test::shipped_scene(name);
    const Particles p = build_particles(scene);
    CHECK(p.soil_count == 2501);
    CHECK(scene.geometry.column_width == 0.04);
    CHECK(scene.geometry.column_height == 0.06);
    CHECK(scene.geometry.wall_withdrawal == WallWithdrawal::Instant);
    CHECK(density(scene.material) == 2000.0);
  }
  CHECK(model_name(test::shipped_scene("collapse-dp").material) == "drucker-prager");
  CHECK(model_name(test::shipped_scene("collapse-mcc").material) == "modified-cam-clay");
}

TEST_CASE("overrides (--set) reach any key and unknown keys are errors", "[scene]") {
  const Scene s = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.002", "numerics.cfl=0.1"});
  CHECK(s.geometry.particle_spacing == 0.002);
  CHECK(s.numerics.cfl == 0.1);
  CHECK(build_particles(s).soil_count == 21 * 31);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.particle_spacin=0.002"}),
                    Contains("[scene] particle_spacin") && Contains("is not a known key"));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"numerics.cfl=2.5"}),
                    Contains("[numerics] cfl = 2.5 is out of range"));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.wall_withdrawal=\"slow\""}),
                    Contains("wall_withdrawal") && Contains("\"instant\", \"none\""));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"solver.steps=3"}),
                    Contains("[solver] is not a known table"));
}

TEST_CASE("[output] fields selects the frame datasets: default all, --set, validation", "[scene][output]") {
  CHECK(test::shipped_scene("collapse-dp").output.fields == FieldSet::all());  // no fields key: all
  CHECK(test::shipped_scene("collapse-mcc").output.fields == FieldSet::all());
  CHECK(test::shipped_scene("collapse-dp", {R"(output.fields=["p","q"])"}).output.fields ==
        FieldSet().insert(Field::p).insert(Field::q));
  CHECK(test::shipped_scene("collapse-dp", {R"(output.fields=["velocity", "speed", "stress", "p", "q",)"
                                            R"( "plastic_strain", "density", "layer"])"})
            .output.fields == FieldSet::all());
  CHECK(test::shipped_scene("collapse-dp", {"output.fields=[]"}).output.fields.empty());  // positions only
  const auto allowed = Contains(R"((allowed: "velocity", "speed", "stress", "p", "q", "plastic_strain", )"
                                R"("density", "layer"))");
  CHECK_THROWS_WITH(
      test::shipped_scene("collapse-dp", {R"(output.fields=["p","sxx"])"}),
      Contains(R"(--set output.fields=["p","sxx"]: [output] fields)") && Contains(R"("sxx" is not allowed)") &&
          allowed);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {R"(output.fields="p")"}),
                    Contains(R"(--set output.fields="p": [output] fields: must be an array)") && allowed);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"output.fields=3"}),
                    Contains("[output] fields: must be an array") && allowed);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"output.fields=[1]"}),
                    Contains("[output] fields: must hold only strings") && allowed);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {R"(output.fields=["p","p"])"}),
                    Contains(R"([output] fields: "p" is listed twice)"));
  CHECK_THROWS_AS(test::shipped_scene("collapse-dp", {R"(output.fields=["P"])"}), ParameterError);
}

TEST_CASE("frame buffers compute only the selected fields", "[scene][output]") {
  const Scene scene = test::shipped_scene("collapse-mcc", {"scene.particle_spacing=0.004"});
  Particles particles = build_particles(scene);
  set_geostatic_state(particles, scene);
  const std::size_t n = particles.soil_count;
  FrameBuffers buffers;
  const Frame all = buffers.view(particles, 0.5);
  for (const std::size_t size :
       {all.sxx.size(), all.syy.size(), all.szz.size(), all.sxy.size(), all.p.size(), all.q.size(),
        all.plastic_strain.size(), all.density.size(), all.layer.size()})
    CHECK(size == n);
  const double p0 = all.p[n / 2];
  const Frame some = buffers.view(particles, 0.5, FieldSet().insert(Field::p).insert(Field::layer));
  CHECK(some.x.size() == n);
  CHECK(some.p.size() == n);
  CHECK(some.p[n / 2] == p0);
  CHECK(some.layer.size() == n);
  for (const std::size_t size : {some.sxx.size(), some.q.size(), some.plastic_strain.size()})
    CHECK(size == 0);
}

TEST_CASE("the initial stress is geostatic and inside the yield surface", "[scene][initial]") {
  const Scene scene = test::shipped_scene("collapse-mcc", {"scene.particle_spacing=0.002"});
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const auto& mcc = std::get<ModifiedCamClay>(scene.material);
  const double rho = 2000.0, g = 9.81, H = 0.06, dx = 0.002, k0 = 0.3 / 0.7;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double sv = rho * g * (H + dx / 2 - p.y[i]);
    CHECK(p.state[i].stress(1, 1) == Approx(-sv));
    CHECK(p.state[i].stress(0, 0) == Approx(-k0 * sv));
    CHECK(p.state[i].stress(2, 2) == Approx(-k0 * sv));
    CHECK(mcc.yield(p.state[i].stress, p.state[i].pc) <= 1e-9 * p.state[i].pc * p.state[i].pc);
    // OCR = 1: on the surface where the floor does not act; the floor bounds p_c at the top.
    CHECK(p.state[i].pc >= 100.0);
  }
  const std::size_t base = 0;  // y = 0, p_c from eq 24 with f = 0
  const double pb = (1 + 2 * k0) / 3 * rho * g * (H + dx / 2), qb = (1 - k0) * rho * g * (H + dx / 2);
  CHECK(p.state[base].pc == Approx(pb + qb * qb / (mcc.M() * mcc.M() * pb)));

  // A lateral stress ratio the D-P cone cannot hold (K0 = 0.3: √J2 > −α_φ I1) is rejected.
  const Scene loose = test::shipped_scene(
      "collapse-dp", {"scene.particle_spacing=0.004", "initial.lateral_stress_ratio=0.3"});
  Particles q = build_particles(loose);
  CHECK_THROWS_WITH(set_geostatic_state(q, loose), Contains("lateral_stress_ratio"));
}

TEST_CASE("the time step is the CFL step on the elastic P-wave speed", "[scene][time-step]") {
  const Scene scene = test::shipped_scene("collapse-dp");
  const SolverSetup setup = make_solver_setup(scene);
  // Table 1: K = E/(3(1−2ν)), G = E/(2(1+ν)), c = √((K + 4G/3)/ρ) = √(E(1−ν)/((1+ν)(1−2ν)ρ)).
  const double c = std::sqrt(1.0e6 * 0.7 / (1.3 * 0.4 * 2000.0));
  CHECK(setup.sound_speed == Approx(c));
  CHECK(setup.sound_speed == Approx(25.94).epsilon(1e-3));
  CHECK(setup.initial_time_step() == Approx(scene.numerics.cfl * 1.3e-3 / c));
  // A moving soil takes Δt = C h / (c + |v|max).
  CHECK(cfl_time_step(0.5, 1e-3, 20.0, 5.0) == Approx(0.5 * 1e-3 / 25.0));
}
