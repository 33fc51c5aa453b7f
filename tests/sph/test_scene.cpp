// Scene input: the shipped scenes, overrides, validation messages, the initial geostatic state.
#include <catch2/catch.hpp>

#include "helpers.h"
#include "sph/frame_buffers.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

TEST_CASE("the shipped scenes hold the paper's column: 41 x 61 = 2501 particles at 1 mm", "[scene]") {
  for (const char* name : {"collapse-dp", "collapse-mcc", "collapse-mc"}) {
    const Scene scene = test::shipped_scene(name);
    const Particles p = build_particles(scene);
    CHECK(p.soil_count == 2501);
    CHECK(scene.geometry.column_width == 0.04);
    CHECK(scene.geometry.column_height == 0.06);
    CHECK(scene.geometry.soil_extent.largest_x == 0.04);  // the column's particle centres reach W and H
    CHECK(scene.geometry.soil_extent.height == 0.06);
    CHECK(scene.geometry.wall_withdrawal == WallWithdrawal::Instant);
    CHECK(density(scene.material) == 2000.0);
  }
  CHECK(model_name(test::shipped_scene("collapse-dp").material) == "drucker-prager");
  CHECK(model_name(test::shipped_scene("collapse-mcc").material) == "modified-cam-clay");
  CHECK(model_name(test::shipped_scene("collapse-mc").material) == "mohr-coulomb");
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
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"numerics.artificial_stress_exponent=0.5"}),
                    Contains("[numerics] artificial_stress_exponent = 0.5 is out of range"));
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
                                            R"( "plastic_strain", "density", "layer", "material"])"})
            .output.fields == FieldSet::all());
  CHECK(test::shipped_scene("collapse-dp", {"output.fields=[]"}).output.fields.empty());  // positions only
  const auto allowed = Contains(R"((allowed: "velocity", "speed", "stress", "p", "q", "plastic_strain", )"
                                R"("density", "layer", "material"))");
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

  // A lateral stress ratio the D-P cone cannot hold (K0 = 0.3: √J2 > −α_φ I1) is rejected when read,
  // with the bound (next test case) in the message.
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004", "initial.lateral_stress_ratio=0.3"}),
                    Contains("lateral_stress_ratio = 0.3") && Contains("0.4209"));
}

/// The D-P cone's bound on K0 for a cohesionless soil: with σxx = σzz = K0 σyy, √J2 = (1 − K0)|σyy|/√3
/// and I1 = (1 + 2K0) σyy, so f = 0 (eq 17) at K0 = (1 − √3 α_φ)/(1 + 2√3 α_φ), α_φ from eq 19.
double dp_lowest_k0(double phi_degrees) {
  const double t = std::tan(phi_degrees * M_PI / 180.0), alpha = t / std::sqrt(9.0 + 12.0 * t * t);
  return (1.0 - std::sqrt(3.0) * alpha) / (1.0 + 2.0 * std::sqrt(3.0) * alpha);
}

TEST_CASE("the default K0 is admissible for every friction angle, and the error states the bound",
          "[scene][initial]") {
  CHECK(dp_lowest_k0(35.0) == Approx(0.4209).margin(1e-4));  // below ν/(1−ν) = 0.4286: the elastic default holds
  CHECK(test::shipped_scene("collapse-dp").initial.lateral_stress_ratio == Approx(0.3 / 0.7));
  for (const double phi : {10.0, 20.0, 25.0, 30.0}) {
    const Scene s = test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.004",
                                                        "material.friction_angle=" + std::to_string(phi)});
    // (the bisection's bound lies inside the yield tolerance 1e-9 of f: admissible by construction)
    CHECK(s.initial.lateral_stress_ratio == Approx(dp_lowest_k0(phi)).epsilon(1e-8));
    Particles p = build_particles(s);
    CHECK_NOTHROW(set_geostatic_state(p, s));
  }
  // Cohesion widens the cone: the bound falls below the cohesionless one.
  const Scene cohesive = test::shipped_scene(
      "collapse-dp", {"scene.particle_spacing=0.004", "material.friction_angle=25", "material.cohesion=100"});
  CHECK(cohesive.initial.lateral_stress_ratio < dp_lowest_k0(25.0));
  CHECK(test::shipped_scene("collapse-mcc").initial.lateral_stress_ratio == Approx(0.3 / 0.7));
}

TEST_CASE("a spacing that does not divide the column is an error naming the nearest that do", "[scene]") {
  // 4 cm x 6 cm: a spacing W/m divides H when 1.5 m is whole, i.e. m even: 0.04/12 and 0.04/14 around 3 mm.
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.003"}),
                    Contains("particle_spacing") && Contains("0.00333333 m and 0.00285714 m"));
  CHECK_NOTHROW(test::shipped_scene("collapse-dp", {"scene.particle_spacing=0.0025"}));  // 16 x 24
  // The file's spacing refused because --set changed the column: the message names the option.
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.column_height=0.0605"}),
                    Contains("does not divide the column") && Contains("[with --set scene.column_height=0.0605]"));
}

TEST_CASE("inputs whose column weight overflows are named as such, not blamed on K0", "[scene]") {
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"material.density=1e308"}),
                    Contains("weight of the column overflows"));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.gravity=1e308"}),
                    Contains("--set scene.gravity=1e308: [scene] gravity = 1e308 is out of range"));
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {"scene.column_height=1e308"}),
                    !Contains("lateral_stress_ratio"));
}

TEST_CASE("the scene as run reads back to the same scene, defaults resolved", "[scene][record]") {
  const Scene s = test::shipped_scene("collapse-mcc", {"scene.particle_spacing=0.002"});
  // Keys the file leaves to defaults are in the record with their values.
  CHECK(s.resolved["initial"]["lateral_stress_ratio"].value<double>() == s.initial.lateral_stress_ratio);
  CHECK(s.resolved["numerics"]["artificial_stress_exponent"].value<double>() == 2.55);
  CHECK(s.resolved["material"]["implicit_alpha"].value<double>() == 0.5);
  CHECK(s.resolved["scene"]["rest_speed"].value<double>() == s.rest.speed);
  const Scene again = parse_scene(scene_toml(s), "scene.toml");
  CHECK(scene_toml(again) == scene_toml(s));
  CHECK(again.geometry.particle_spacing == 0.002);
  CHECK(again.rest.duration == s.rest.duration);
  CHECK(std::get<ModifiedCamClay>(again.material).M() == std::get<ModifiedCamClay>(s.material).M());
  CHECK(scene_json(s).find("\"lateral_stress_ratio\"") != std::string::npos);
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
