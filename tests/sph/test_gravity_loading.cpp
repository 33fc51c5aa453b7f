// The gravity-loading stage (sph/gravity_loading.h): a box of soil between walls relaxes to the
// geostatic state it started from and stops at rest; MCC's p_c follows the relaxed stress with the
// scene's OCR; a slope's face gains the shear stress K0 lacks.
#include <catch2/catch.hpp>

#include <cmath>

#include "helpers.h"
#include "../common/material_toml.h"
#include "sph/diagnostics.h"
#include "sph/gravity_loading.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
const std::string kBox = R"(
[scene]
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
[initial]
stress = "gravity-loading"
[[regions]]
shape = "box"
min = [0.0, 0.0]
max = [0.04, 0.04]
[[boundaries]]
kind = "no-slip"
points = [[0.0, 0.0], [0.04, 0.0]]
[[boundaries]]
kind = "free-slip"
points = [[0.04, 0.0], [0.04, 0.08]]
[[boundaries]]
kind = "free-slip"
points = [[0.0, 0.08], [0.0, 0.0]]
removed_at = 0.0
)";
const std::string& kDruckerPrager = fixtures::kDruckerPragerToml;
}  // namespace

TEST_CASE("gravity loading: a box between walls settles at rho g depth and at rest", "[scene][initial][gravity]") {
  // The left wall is withdrawn at t = 0: it holds the soil during the relaxation all the same.
  const Scene scene = test::scene_from_text(kBox + kDruckerPrager);
  REQUIRE(scene.initial.stress == InitialStress::GravityLoading);
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const GravityLoadingReport r = relax_under_gravity(scene, p);
  CHECK(r.steps > 0);
  CHECK(max_speed(p) == 0.0);
  REQUIRE(all_finite(p));
  // Equilibrium, which the relaxation's exit test (kinetic energy, stress change per step) does not
  // check itself: one step of the momentum equation from the relaxed state accelerates the soil
  // vertically by less than 1 % of g on average (the floor's ghosts carry its weight: Σ m a_y =
  // −Σ m g + the floor's force). The soil within the kernel's support 2h = 1.04 cm of the withdrawn
  // left wall is left out: its wall is gone at t = 0, so it is no longer held.
  {
    Particles q = p;
    const SolverSetup setup = make_solver_setup(scene);
    Workspace work(setup, q);
    advance(std::get<DruckerPrager>(scene.material), setup, q, work, setup.initial_time_step());
    double mass = 0.0, momentum_rate = 0.0;
    for (std::size_t i = 0; i < q.soil_count; ++i)
      if (q.x0[i] > 2.0 * 1.3 * 0.004) mass += q.mass[i], momentum_rate += q.mass[i] * q.ay[i];
    CHECK(std::abs(momentum_rate / mass) < 0.01 * 9.81);
  }
  // Mid-depth, away from the walls: the rows at y = 0.018 and 0.022 (depths 0.022 and 0.018 below the
  // top 0.04). Their mean σyy within 3 % of −ρ g × 0.02. The mean of two rows, not each: the relaxed
  // SPH stress carries a row-to-row (odd-even) oscillation that the momentum equation does not see
  // (measured ±24 % at 4 mm; docs/reference/scenes.md).
  const double rho_g = 2000.0 * 9.81;
  double sum = 0.0;
  int checked = 0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    if (std::abs(p.y[i] - 0.02) > 0.0025 || p.x[i] < 0.008 || p.x[i] > 0.032) continue;
    ++checked;
    sum += p.syy[i];
  }
  CHECK(checked >= 10);
  CHECK(sum / checked == Approx(-rho_g * 0.02).epsilon(0.03));
}

TEST_CASE("gravity loading: MCC's p_c follows the relaxed stress and the OCR", "[scene][initial][gravity]") {
  for (const double ocr : {1.0, 2.0}) {
    const Scene scene = test::scene_from_text(kBox + fixtures::kCamClayToml + R"(elasticity = "constant"
young_modulus = 1.0e6
)", {"initial.overconsolidation_ratio=" + std::to_string(ocr)});
    Particles p = build_particles(scene);
    set_geostatic_state(p, scene);
    relax_under_gravity(scene, p);
    const auto& mcc = std::get<ModifiedCamClay>(scene.material);
    for (std::size_t i = 0; i < p.soil_count; ++i) {
      const Mat3& s = p.state[i].stress;
      const double pm = -s.trace() / 3.0;
      const double q = std::sqrt(1.5) * (s - Mat3::Identity() * (s.trace() / 3.0)).norm();
      const double on_surface = pm + q * q / (mcc.M() * mcc.M() * pm);  // eq 24: p_c through (p, q)
      CHECK(p.state[i].pc == Approx(std::max(ocr * on_surface, scene.initial.preconsolidation_floor)).epsilon(1e-12));
      CHECK(p.state[i].plastic_shear_strain == 0.0);
    }
  }
}

TEST_CASE("gravity loading: the slope's face gains shear stress, and the keys are validated", "[scene][initial][gravity]") {
  const Scene slope = test::shipped_scene("slope", {"scene.particle_spacing=0.004", R"(initial.stress="gravity-loading")"});
  Particles p = build_particles(slope);
  set_geostatic_state(p, slope);
  const GravityLoadingReport r = relax_under_gravity(slope, p);
  CHECK(r.kinetic_energy < 1e-8);
  // Under the middle of the face, at mid-height: K0 has σxy = 0 there; the relaxed soil carries the
  // shear a face needs, a clear fraction of its vertical stress.
  double largest_ratio = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i)
    if (p.x[i] > 0.04 && p.x[i] < 0.08 && p.y[i] < 0.5 * p.x[i] - 0.01)
      largest_ratio = std::max(largest_ratio, std::abs(p.sxy[i] / p.syy[i]));
  CHECK(largest_ratio > 0.05);

  CHECK_THROWS_WITH(test::shipped_scene("slope", {"initial.gravity_loading_damping=0.1"}),
                    Contains("gravity_loading_damping") && Contains("gravity-loading"));
  CHECK_THROWS_WITH(
      test::shipped_scene("slope", {R"(initial.stress="gravity-loading")", "initial.gravity_loading_damping=1.5"}),
      Contains("gravity_loading_damping"));
  // Too short to settle: an error that states what was reached.
  Scene hurried = test::shipped_scene(
      "slope", {"scene.particle_spacing=0.004", R"(initial.stress="gravity-loading")", "initial.gravity_loading_max_time=0.001"});
  Particles q = build_particles(hurried);
  set_geostatic_state(q, hurried);
  CHECK_THROWS_WITH(relax_under_gravity(hurried, q), Contains("did not settle") && Contains("kinetic energy"));
}
