// The gravity-loading stage in space (sph/gravity_loading.h, the plane's relax_under_gravity for
// dim = 3): a box of soil between walls, one of them withdrawn at t = 0, relaxes to the geostatic
// state and stops at rest; a run continued from a checkpoint does not relax again; the [initial]
// keys are read and validated in 3D as in 2D.
#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "../common/lattice_sums.h"
#include "../common/material_toml.h"
#include "sph/collapse_3d.h"
#include "sph/diagnostics.h"
#include "sph/gravity_loading.h"
#include "sph/initial_state_3d.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

namespace {
// The slab shorthand as a box: soil on the nodes (iΔp, jΔp, (k + ½)Δp), 7 × 9 × 4 of them at 4 mm,
// between the free-slip fixed wall x = W + Δp/2, the removable wall x = −Δp/2 (withdrawn at t = 0,
// so it holds the soil only while it relaxes), the free-slip planes z = 0 and z = T and the no-slip
// floor y = −Δp/2.
const std::string kBox = R"(
[scene]
dimension = 3
column_width = 0.024
column_height = 0.032
slab_thickness = 0.016
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.1
gravity = 9.81
wall_withdrawal = "instant"
floor_length = 0.028
[initial]
stress = "gravity-loading"
)" + fixtures::kDruckerPragerToml;

constexpr double kRho = 2000.0, kG = 9.81, kSpacing = 0.004, kH = 0.032, kW = 0.024;

Scene3 box(std::vector<std::string> overrides = {}) {
  return parse_scene_3d(kBox, "box.toml", overrides);
}

/// Mean of σ_ab / σ_yy... and σ_yy over the soil of the rows at heights `rows` (m) that lies at
/// least two spacings from the walls x = 0 and x = W.
struct RowMeans {
  int count = 0;
  double syy = 0.0, sxx = 0.0, szz = 0.0, depth = 0.0;
};
RowMeans row_means(const ParticlesOf<3>& p, std::initializer_list<double> rows) {
  RowMeans m;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    bool in_row = false;
    for (double y : rows) in_row = in_row || std::abs(p.y[i] - y) < 0.25 * kSpacing;
    if (!in_row || p.x[i] < 1.75 * kSpacing || p.x[i] > kW - 1.75 * kSpacing) continue;
    ++m.count;
    m.syy += p.syy[i], m.sxx += p.sxx[i], m.szz += p.szz[i];
    m.depth += kH + 0.5 * kSpacing - p.y[i];  // below the flat top H + Δp/2 of every lattice column
  }
  m.syy /= m.count, m.sxx /= m.count, m.szz /= m.count, m.depth /= m.count;
  return m;
}

/// Least-squares slope dσ_yy/dy (Pa/m, tension-positive) of the mean σ_yy of the soil rows at
/// heights `rows` (m) that lies at least two spacings from the walls x = 0 and x = W.
double vertical_stress_gradient(const ParticlesOf<3>& p, const std::vector<double>& rows) {
  double sy = 0.0, ss = 0.0, syy = 0.0, sys = 0.0;
  for (double y : rows) {
    const double s = row_means(p, {y}).syy;
    sy += y, ss += s, syy += y * y, sys += y * s;
  }
  const double n = static_cast<double>(rows.size());
  return (n * sys - sy * ss) / (n * syy - sy * sy);
}
}  // namespace

TEST_CASE("gravity loading in 3D: a box between walls settles at rho g depth, K0 across, and at rest",
          "[collapse-3d][initial][gravity]") {
  const Scene3 scene = box();
  REQUIRE(scene.initial.stress == InitialStress::GravityLoading);
  REQUIRE(scene.geometry.withdrawn_walls.size() == 1);  // the removable wall, not built for the run
  // ν/(1 − ν): the elastic K0, which an oedometric settling of the elastic soil keeps
  // (Δσ_h = ν/(1 − ν) Δσ_v under ε_x = ε_z = 0).
  const double k0 = scene.initial.lateral_stress_ratio;
  REQUIRE(k0 == Approx(0.3 / 0.7).epsilon(1e-12));

  Collapse3 collapse(scene);
  REQUIRE(collapse.gravity_loading().has_value());
  const GravityLoadingReport& r = *collapse.gravity_loading();
  const ParticlesOf<3>& p = collapse.particles();
  CHECK(r.steps > 0);
  CHECK(r.kinetic_energy < scene.initial.gravity_loading.kinetic_tolerance);
  CHECK(r.stress_change < scene.initial.gravity_loading.stress_tolerance);
  CHECK(kinetic_energy(p) == 0.0);
  // The soil moved while it relaxed (the K0 field of a lattice is not the SPH equilibrium), and
  // its displacements count from where it settled.
  const ParticlesOf<3> as_built = geostatic_particles(scene);
  double moved = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    moved = std::max(moved, std::abs(p.y[i] - as_built.y[i]));
    REQUIRE(p.start_position(i) == p.position(i));
  }
  CHECK(moved > 0.0);

  // Equilibrium, which the exit test (kinetic energy, stress change per step) does not check
  // itself: one step of the momentum equation from the relaxed state accelerates the soil
  // vertically by less than 1 % of g on average (Σ m a_y = −Σ m g + the floor's force). The soil
  // within the kernel's support 2h of the withdrawn wall is left out: from t = 0 it is not held.
  {
    ParticlesOf<3> q = p;
    const SolverSetupOf<3>& setup = collapse.setup();
    WorkspaceOf<3> work(setup, q);
    advance(std::get<DruckerPrager>(scene.material), setup, q, work, setup.initial_time_step());
    double mass = 0.0, momentum_rate = 0.0;
    for (std::size_t i = 0; i < q.soil_count; ++i)
      if (q.x0[i] > 2.0 * 1.3 * kSpacing) mass += q.mass[i], momentum_rate += q.mass[i] * q.ay[i];
    CHECK(std::abs(momentum_rate / mass) < 0.01 * kG);
  }

  // Mid-depth, two spacings from both walls: the rows y = 0.012 and 0.016 m. The mean of two rows,
  // as in 2D (the relaxed SPH stress oscillates from row to row, docs/reference/scenes.md):
  // σyy = −ρ g depth within 3 % (measured 1.9 % above it: the gradient below, over a depth of 5 Δp),
  // and σxx, σzz = K0 σyy within 5 % (the free-slip walls and planes hold ε_x = ε_z = 0: the
  // settling adds ν/(1 − ν) of its vertical stress across; measured within 0.4 %).
  const RowMeans m = row_means(p, {0.012, 0.016});
  INFO("rows: " << m.count << " particles, depth " << m.depth << " m, syy " << m.syy << " sxx " << m.sxx
                << " szz " << m.szz << " Pa");
  REQUIRE(m.count == 2 * 3 * 4);
  CHECK(m.syy == Approx(-kRho * kG * m.depth).epsilon(0.03));
  // The vertical stress gradient over the rows below the top two is SPH's equilibrium gradient ρg/M
  // (M = 0.9935 for the cubic spline at h = 1.3 Δp: 0.65 % steeper than ρg) within 1 % (measured
  // 0.8 % steeper still in this box; 0.4 % in a box twice as wide, 0.1 % at half the spacing).
  // M = Σ_j V_j (y_j − y_i) ∂W_ij/∂y_i over a full lattice (1 in the continuum): a linear stress
  // field's SPH divergence (eq 12) is M times its exact one, so SPH equilibrium under gravity holds
  // a vertical stress gradient of ρg/M (derivation in docs/method/sph-3d.md).
  const double moment = -test::lattice_sums(CubicSplineKernel<3>(1.3 * kSpacing), kSpacing).moment[1][1];
  REQUIRE(moment == Approx(0.9935).epsilon(1e-3));
  const double gradient = vertical_stress_gradient(p, {0.0, 0.004, 0.008, 0.012, 0.016, 0.020, 0.024});
  CHECK(gradient == Approx(kRho * kG / moment).epsilon(0.01));
  CHECK(std::abs(gradient / (kRho * kG / moment) - 1.0) < std::abs(gradient / (kRho * kG) - 1.0));
  CHECK(m.sxx / m.syy == Approx(k0).epsilon(0.05));
  CHECK(m.szz / m.syy == Approx(k0).epsilon(0.05));

  // A run continued from a checkpoint's particles does not relax them again.
  const Collapse3 resumed(scene, p);
  CHECK_FALSE(resumed.gravity_loading().has_value());
  CHECK(resumed.particles().y == p.y);
  CHECK(resumed.particles().syy == p.syy);
}

TEST_CASE("gravity loading in 3D: the [initial] keys and the walls withdrawn at t = 0",
          "[scene-3d][initial][gravity]") {
  // The relaxation's keys only with "gravity-loading", in range.
  CHECK_THROWS_WITH(box({R"(initial.stress="local-surface")", "initial.gravity_loading_damping=0.1"}),
                    Contains("gravity_loading_damping") && Contains("gravity-loading"));
  CHECK_THROWS_WITH(box({"initial.gravity_loading_damping=1.5"}), Contains("gravity_loading_damping"));
  CHECK_THROWS_WITH(box({"initial.gravity_loading_max_time=0"}), Contains("gravity_loading_max_time"));
  // The scene as run records them.
  const Scene3 scene = box({"initial.gravity_loading_damping=0.05"});
  CHECK(scene.initial.gravity_loading.damping == 0.05);
  const Scene3 again = parse_scene_3d(scene_toml(scene), "scene.toml");
  CHECK(again.initial.stress == InitialStress::GravityLoading);
  CHECK(again.initial.gravity_loading.damping == 0.05);

  // Too short to settle: an error that states what was reached.
  const Scene3 hurried = box({"initial.gravity_loading_max_time=0.001"});
  ParticlesOf<3> q = geostatic_particles(hurried);
  CHECK_THROWS_WITH(relax_under_gravity(hurried, q),
                    Contains("did not settle") && Contains("kinetic energy"));

  // A [[boundaries]] wall removed at t = 0 is kept aside for the relaxation, not built for the run;
  // the slab's removable wall is built when it is not withdrawn at once.
  const Scene3 with_gate = parse_scene_3d(kBox + R"(
[[boundaries]]
shape = "rectangle"
kind = "free-slip"
corner = [0.03, -0.002, 0.0]
edges = [[0.0, 0.0, 0.016], [0.0, 0.04, 0.0]]
removed_at = 0.0
name = "gate"
)",
                                          "box.toml");
  REQUIRE(with_gate.geometry.withdrawn_walls.size() == 2);
  CHECK(with_gate.geometry.withdrawn_walls[1].label == "gate");
  for (const Wall3& w : with_gate.geometry.walls) CHECK(w.label != "gate");
  const Scene3 kept = box({R"(scene.wall_withdrawal="none")"});
  CHECK(kept.geometry.withdrawn_walls.empty());
  CHECK(build_particles_3d(kept).boundary_count() > build_particles_3d(scene).boundary_count());
}
