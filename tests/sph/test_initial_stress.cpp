// The geostatic stress under the local free surface: the same as the flat surface
// for a box, the depth below the slope face for a polygon, the highest soil under an overhang.
#include <catch2/catch.hpp>

#include "helpers.h"
#include "sph/geometry/surface.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
const std::string kMaterial = R"(
[material]
model = "drucker-prager"
density = 2000.0
young_modulus = 1.0e6
poisson_ratio = 0.3
friction_angle = 25.0
cohesion = 100.0
)";

Particles geostatic(const Scene& scene) {
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  return p;
}
}  // namespace

TEST_CASE("local-surface K0 under a box is the flat surface's, bit for bit", "[scene][initial][surface]") {
  // The column shorthand and a box region, the former's surface H + Δp/2, the latter's its top edge.
  for (const bool shorthand : {true, false}) {
    const Scene flat =
        shorthand ? test::shipped_scene("collapse-mcc", {"scene.particle_spacing=0.004"})
                  : test::scene_from_text(R"(
[scene]
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
[[regions]]
shape = "box"
min = [0.0, 0.0]
max = [0.04, 0.06]
)" + kMaterial);
    Scene local = flat;
    local.initial.stress = InitialStress::LocalSurface;
    const Particles a = geostatic(flat), b = geostatic(local);
    REQUIRE(a.soil_count == b.soil_count);
    for (std::size_t i = 0; i < a.soil_count; ++i) {
      CHECK(a.sxx[i] == b.sxx[i]);
      CHECK(a.syy[i] == b.syy[i]);
      CHECK(a.sxy[i] == b.sxy[i]);
      CHECK(a.state[i].stress(2, 2) == b.state[i].stress(2, 2));
      CHECK(a.state[i].pc == b.state[i].pc);
    }
  }
}

TEST_CASE("local-surface K0 under a 2:1 slope is rho g times the depth below the face", "[scene][initial][surface]") {
  // Toe at the origin, face rising 1 in 2 to the crest at (0.1, 0.05), level crest to x = 0.2: the
  // surface is y_s(x) = x/2 for x ≤ 0.1 and 0.05 beyond. Every particle: σyy = −ρ g (y_s(x) − y),
  // σxx = σzz = K0 σyy (the closed form, to round-off of ρ g H).
  const Scene scene = test::scene_from_text(R"(
[scene]
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
[initial]
stress = "local-surface"
lateral_stress_ratio = 0.5
[[regions]]
shape = "polygon"
points = [[0.0, 0.0], [0.2, 0.0], [0.2, 0.05], [0.1, 0.05]]
)" + kMaterial);
  const Particles p = geostatic(scene);
  const double rho_g = 2000.0 * 9.81, H = 0.05, k0 = 0.5;
  int under_face = 0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double surface = p.x[i] <= 0.1 ? 0.5 * p.x[i] : 0.05;
    const double sv = -rho_g * (surface - p.y[i]);
    under_face += p.x[i] < 0.1;
    CHECK(p.syy[i] == Approx(sv).margin(1e-12 * rho_g * H));
    CHECK(p.sxx[i] == Approx(k0 * sv).margin(1e-12 * rho_g * H));
    CHECK(p.state[i].stress(2, 2) == Approx(k0 * sv).margin(1e-12 * rho_g * H));
    CHECK(p.sxy[i] == 0.0);
  }
  CHECK(under_face > 100);
  // The flat surface (the default) hangs the face's particles from the crest level instead.
  Scene flat = scene;
  flat.initial.stress = InitialStress::FlatSurface;
  const Particles q = geostatic(flat);
  for (std::size_t i = 0; i < q.soil_count; ++i) CHECK(q.syy[i] == Approx(-rho_g * (0.05 - q.y[i])).margin(1e-12 * rho_g * H));
}

TEST_CASE("the free surface above a point: highest soil under an overhang, any gravity", "[scene][initial][surface]") {
  // A Γ: a stem [0, 1] × [0, 2] with an arm [1, 3] × [1.5, 2] over air. Under the arm the highest
  // soil is its top, 2, with air between (documented: counted as soil).
  const std::vector<Region> gamma{{Region::Shape::Polygon,
                                   {{0, 0}, {1, 0}, {1, 1.5}, {3, 1.5}, {3, 2}, {0, 2}},
                                   "",
                                   "gamma",
                                   {}}};
  const Vec2 down{0.0, -1.0};
  CHECK(surface_height_above(gamma, down, {2.0, 0.5}) == 2.0);
  CHECK(surface_height_above(gamma, down, {0.5, 0.5}) == 2.0);
  CHECK(surface_height_above(gamma, down, {4.0, 0.5}) == -std::numeric_limits<double>::infinity());
  // On the vertical edge x = 3 the higher end counts.
  CHECK(surface_height_above(gamma, down, {3.0, 1.0}) == 2.0);
  // Two regions on one vertical: the higher wins. Gravity along −x: "up" is +x, the surface the
  // rightmost soil on the horizontal through the point.
  const std::vector<Region> two{{Region::Shape::Box, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "", "a", {}},
                                {Region::Shape::Box, {{0, 3}, {1, 3}, {1, 4}, {0, 4}}, "", "b", {}}};
  CHECK(surface_height_above(two, down, {0.5, 0.5}) == 4.0);
  CHECK(surface_height_above(two, {-1.0, 0.0}, {0.5, 0.5}) == 1.0);
  CHECK(surface_height_above(two, {-1.0, 0.0}, {-5.0, 3.5}) == 1.0);
}

TEST_CASE("[initial] stress is validated", "[scene][initial][surface]") {
  CHECK(test::shipped_scene("collapse-dp").initial.stress == InitialStress::FlatSurface);
  CHECK(test::shipped_scene("collapse-dp", {R"(initial.stress="local-surface")"}).initial.stress ==
        InitialStress::LocalSurface);
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", {R"(initial.stress="local")"}),
                    Contains("[initial] stress") && Contains("local-surface"));
}

TEST_CASE("a cohesionless D-P of vanishing friction takes the one K0 its cone holds", "[scene][initial]") {
  // The input fuzzer's last finding: φ = 3.5e-29°, c = 0 defaulted K0 to 1 (the isotropic state, on
  // the degenerate cone's axis) and then refused it at points where σ = vI has a round-off deviator.
  const std::vector<std::string> slender = {"material.friction_angle=3.5e-29", "material.cohesion=0",
                                            "scene.particle_spacing=0.004"};
  const Scene scene = test::shipped_scene("collapse-dp", slender);
  CHECK(scene.initial.material_lateral_stress_ratio[0] == 1.0);
  const Particles p = geostatic(scene);
  for (std::size_t i = 0; i < p.soil_count; ++i) REQUIRE(p.sxx[i] == p.syy[i]);
  // Given explicitly, K0 = 1 is taken; any other K0 is outside that cone, and the error says which.
  std::vector<std::string> given = slender;
  given.push_back("initial.lateral_stress_ratio=1");
  CHECK_NOTHROW(geostatic(test::shipped_scene("collapse-dp", given)));
  given.back() = "initial.lateral_stress_ratio=0.999999";
  CHECK_THROWS_WITH(test::shipped_scene("collapse-dp", given),
                    Contains("lateral_stress_ratio") && Contains("1 <= value <= 1"));
}
