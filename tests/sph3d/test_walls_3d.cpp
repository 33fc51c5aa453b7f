// Walls of space as data and in motion: [[boundaries]] rectangles and polygons in a 3D scene and
// their reader's refusals; a moving wall's ghosts displaced by its velocity over each step and
// massless once it is removed, when the soil no longer feels it; the slab's gate lifted at its
// speed; the wall guard following a moving plane; a particle gliding on an inclined free-slip plane
// and a block on an inclined frictional plane against Coulomb's law.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "../common/material_toml.h"
#include "../common/particle_arrays.h"
#include "sph/analysis/boundary_forces.h"
#include "sph/collapse_3d.h"
#include "sph/geometry/extrusion.h"
#include "sph/geometry/planar_ghosts.h"
#include "sph/initial_state_3d.h"
#include "sph/scene_3d.h"
#include "sph/solver.h"

using soilsph::LinearElastic;
using soilsph::ParameterError;
using namespace soilsph::sph;
namespace fixtures = soilsph::fixtures;

namespace {

const std::string kSlab = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/slab-3d.toml";

/// A small slab released at t = 0 (2 cm × 2 cm, 8 mm thick at 4 mm: 6 × 6 × 2 soil particles),
/// elastic, with `scene` keys and `tables` appended.
std::string small_slab(const std::string& scene, const std::string& tables) {
  return R"(
[scene]
dimension = 3
column_width = 0.02
column_height = 0.02
slab_thickness = 0.008
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.02
wall_withdrawal = "instant"
)" + scene +
         "\n" + fixtures::kLinearElasticToml + tables;
}

std::size_t wall_named(const Scene3& scene, const std::string& label) {
  for (std::size_t w = 0; w < scene.geometry.walls.size(); ++w)
    if (scene.geometry.walls[w].label == label) return w;
  FAIL("no wall " << label);
  return 0;
}

/// The message of the ParameterError that reading `text` throws ("" if none).
std::string refusal(const std::string& text) {
  try {
    (void)parse_scene_3d(text, "walls.toml");
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

/// A plate at the slab's released side x = −Δp/2, across the slab's thickness, up to 3 cm.
const std::string kPlate = R"(
[[boundaries]]
shape = "rectangle"
name = "plate"
kind = "free-slip"
corner = [-0.002, -0.002, 0.0]
edges = [[0.0, 0.032, 0.0], [0.0, 0.0, 0.008]]
)";

}  // namespace

TEST_CASE("[[boundaries]] in space: a rectangle and a polygon become planar walls of the scene",
          "[walls-3d]") {
  const Scene3 s = parse_scene_3d(small_slab("gravity = 9.81", kPlate + R"(
[[boundaries]]
shape = "polygon"
kind = "frictional"
wall_friction_angle = 20.0
points = [[0.1, 0.0, 0.0], [0.1, 0.0, 0.008], [0.1, 0.02, 0.008]]
normal = [-2.0, 0.0, 0.0]
removed_at = 0.5
)"),
                                  "walls.toml");
  const Wall3& plate = s.geometry.walls[wall_named(s, "plate")];
  // a × b = (0, 0.032, 0) × (0, 0, 0.008) along +x: the soil at x > −Δp/2.
  CHECK(plate.plane.inward.x == Approx(1.0));
  CHECK(plate.kind == WallKind::FreeSlip);
  CHECK(!plate.motion.changes());
  const Wall3& far = s.geometry.walls[wall_named(s, "boundary_2")];  // the default name of the second table
  // The points' right-hand rule gives +x; normal = [−2, 0, 0] turns the soil's side to −x.
  CHECK(far.plane.inward.x == Approx(-1.0));
  CHECK(far.kind == WallKind::Frictional);
  CHECK(far.friction_angle == 20.0);
  CHECK(far.motion.removed_at == 0.5);
  // The domain holds the far wall and its ghost layers.
  CHECK(s.geometry.domain.hi.x > 0.1);
  // The scene as run reads back to the same walls.
  const Scene3 again = parse_scene_3d(scene_toml(s), "again.toml");
  REQUIRE(again.geometry.walls.size() == s.geometry.walls.size());
  const Wall3& far_again = again.geometry.walls[wall_named(again, "boundary_2")];
  CHECK(far_again.plane.inward.x == Approx(-1.0));
  CHECK(far_again.motion.removed_at == 0.5);
  // The ramp of docs/reference/scenes.md: a × b along (sin 30°, cos 30°, 0), towards the soil.
  std::ifstream in(kSlab);
  const std::string slab((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Scene3 ramp = parse_scene_3d(slab + R"(
[[boundaries]]
shape = "rectangle"
name = "ramp"
kind = "frictional"
wall_friction_angle = 25.0
corner = [-0.1, -0.0005, 0.0]
edges = [[-0.1732, 0.1, 0.0], [0.0, 0.0, 0.01]]
)",
                                     kSlab);
  const Vec3 up_slope = ramp.geometry.walls[wall_named(ramp, "ramp")].plane.inward;
  CHECK(up_slope.x == Approx(0.5).epsilon(1e-4));
  CHECK(up_slope.y == Approx(std::sqrt(0.75)).epsilon(1e-4));
  CHECK(up_slope.z == Approx(0.0).margin(1e-12));
  // A wall removed at 0 is never there.
  const Scene3 none = parse_scene_3d(small_slab("", kPlate + "removed_at = 0.0\n"), "walls.toml");
  CHECK(none.geometry.walls.size() == s.geometry.walls.size() - 2);
}

TEST_CASE("every refusal of a 3D [[boundaries]] table names the file, the table, the key and what is allowed",
          "[walls-3d]") {
  const auto refused = [](const std::string& table) {
    return refusal(small_slab("", "[[boundaries]]\n" + table));
  };
  const std::string rectangle =
      "shape = \"rectangle\"\ncorner = [0.0, 0.0, 0.0]\nedges = [[0.0, 0.01, 0.0], [0.0, 0.0, 0.01]]\n";
  using Catch::Matchers::Contains;
  CHECK_THAT(refused("kind = \"free-slip\"\n"), Contains("walls.toml") && Contains("[boundaries #1] shape"));
  CHECK_THAT(refused(rectangle), Contains("[boundaries #1] kind") && Contains("free-slip"));
  CHECK_THAT(refused(rectangle + "kind = \"rough\"\n"), Contains("[boundaries #1] kind"));
  CHECK_THAT(refused(rectangle + "kind = \"frictional\"\n"),
             Contains("[boundaries #1] wall_friction_angle") && Contains("90"));
  CHECK_THAT(refused(rectangle + "kind = \"frictional\"\nwall_friction_angle = 95.0\n"),
             Contains("wall_friction_angle") && Contains("90"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nfriction_angle = 30.0\n"),
             Contains("friction_angle"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nremoved_at = -1.0\n"), Contains("removed_at"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nend = 1.0\n"),
             Contains("[boundaries #1] end") && Contains("velocity"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nvelocity = [0.0, 1.0]\nend = 1.0\n"),
             Contains("velocity") && Contains("[x, y, z]"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nvelocity = [0.0, 1.0, 0.0]\n"), Contains("end"));
  CHECK_THAT(
      refused(rectangle + "kind = \"free-slip\"\nvelocity = [0.0, 1.0, 0.0]\nstart = 2.0\nend = 1.0\n"),
      Contains("end"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nname = \"floor\"\n"),
             Contains("[boundaries #1] name") && Contains("floor"));
  CHECK_THAT(refused(rectangle + "kind = \"free-slip\"\nname = \"a b\"\n"), Contains("name"));
  const std::string free_rectangle = "shape = \"rectangle\"\nkind = \"free-slip\"\n";
  CHECK_THAT(
      refused(free_rectangle + "corner = [0.0, 0.0, 0.0]\nedges = [[0.0, 0.01, 0.0], [0.0, 0.01, 0.01]]\n"),
      Contains("[boundaries #1] edges") && Contains("perpendicular"));
  CHECK_THAT(
      refused(free_rectangle + "corner = [0.0, 0.0, 0.0]\nedges = [[0.0, 0.0, 0.0], [0.0, 0.0, 0.01]]\n"),
      Contains("[boundaries #1] edges") && Contains("zero length"));
  CHECK_THAT(refused(free_rectangle + "corner = [0.0, 0.0, 0.0]\nedges = [[0.0, 0.01, 0.0]]\n"),
             Contains("[boundaries #1] edges") && Contains("two edges"));
  CHECK_THAT(refused(free_rectangle + "corner = [0.0, 0.0]\nedges = [[0.0, 0.01, 0.0], [0.0, 0.0, 0.01]]\n"),
             Contains("[boundaries #1] corner") && Contains("[x, y, z]"));
  CHECK_THAT(refused(free_rectangle + "edges = [[0.0, 0.01, 0.0], [0.0, 0.0, 0.01]]\n"),
             Contains("[boundaries #1] corner") && Contains("missing"));
  const std::string polygon = "shape = \"polygon\"\nkind = \"free-slip\"\n";
  CHECK_THAT(refused(polygon + "points = [[0.0, 0.0, 0.0], [0.0, 0.01, 0.0]]\n"),
             Contains("[boundaries #1] points") && Contains("at least 3"));
  CHECK_THAT(refused(polygon + "points = [[0.0, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.02, 0.0]]\n"),
             Contains("[boundaries #1] points") && Contains("zero area"));
  CHECK_THAT(refused(polygon +
                     "points = [[0.0, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.01, 0.01], [0.001, 0.0, 0.01]]\n"),
             Contains("[boundaries #1] points") && Contains("off the plane"));
  CHECK_THAT(
      refused(polygon +
              "points = [[0.0, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.01, 0.01]]\nnormal = [0.0, 1.0, 0.0]\n"),
      Contains("[boundaries #1] normal") && Contains("degrees off"));
  CHECK_THAT(
      refused(polygon +
              "points = [[0.0, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.01, 0.01]]\ncorner = [0.0, 0.0, 0.0]\n"),
      Contains("corner"));
}

TEST_CASE("a symmetry plane of space is free slip mirrored by the soil's images, named as written, kind kept",
          "[walls-3d]") {
  // The plate of kPlate at the slab's released side, written as a symmetry plane: the soil mirrored
  // across x = −0.002 m by its own images (stages/mirror_images.h), not by ghosts on the lattice.
  std::string mirror = kPlate;
  mirror.replace(mirror.find("free-slip"), 9, "symmetry");
  const Scene3 free_slip = parse_scene_3d(small_slab("", kPlate), "walls.toml");
  const Scene3 symmetric = parse_scene_3d(small_slab("", mirror), "walls.toml");
  const Wall3& plate = symmetric.geometry.walls[wall_named(symmetric, "plate")];
  CHECK(plate.kind == WallKind::FreeSlip);
  CHECK(plate.friction_angle == 0.0);
  CHECK(!plate.motion.changes());
  // The free-slip plate's lattice ghosts are all the symmetry plane does not have.
  const ParticlesOf<3> with_ghosts = build_particles_3d(free_slip), with_images = build_particles_3d(symmetric);
  const auto plate_ghosts = static_cast<std::size_t>(
      std::count(with_ghosts.wall_id.begin(), with_ghosts.wall_id.end(), static_cast<int>(wall_named(free_slip, "plate"))));
  REQUIRE(plate_ghosts > 0);
  CHECK(with_images.boundary_count() == with_ghosts.boundary_count() - plate_ghosts);
  CHECK(std::count(with_images.wall_id.begin(), with_images.wall_id.end(),
                   static_cast<int>(wall_named(symmetric, "plate"))) == 0);
  // The setup mirrors the soil across it: x = −Δp/2, the soil on the side of +x.
  const std::vector<SymmetryPlane> planes = make_solver_setup(symmetric).symmetry_planes;
  const auto mirrored = std::find_if(planes.begin(), planes.end(), [&](const SymmetryPlane& plane) {
    return plane.wall == static_cast<int>(wall_named(symmetric, "plate"));
  });
  REQUIRE(mirrored != planes.end());
  CHECK(mirrored->axis == 0);
  CHECK(mirrored->side == 1.0);
  CHECK(mirrored->offset == Approx(-0.002).margin(1e-15));
  CHECK(make_solver_setup(free_slip).symmetry_planes.size() + 1 == planes.size());
  // The scene as run says "symmetry", under the plate's name, and reads back to it.
  const toml::table& resolved = *symmetric.resolved["boundaries"].as_array()->front().as_table();
  CHECK(resolved["kind"].value_or(std::string()) == "symmetry");
  CHECK(resolved["name"].value_or(std::string()) == "plate");
  CHECK(!resolved.contains("wall_friction_angle"));
  const Scene3 again = parse_scene_3d(scene_toml(symmetric), "again.toml");
  CHECK(scene_toml(again) == scene_toml(symmetric));
  CHECK(again.geometry.walls[wall_named(again, "plate")].kind == WallKind::FreeSlip);
}

TEST_CASE("a symmetry plane of space takes no friction angle and does not move: errors name file and key",
          "[walls-3d]") {
  using Catch::Matchers::Contains;
  const std::string symmetry =
      "[[boundaries]]\nshape = \"rectangle\"\nkind = \"symmetry\"\ncorner = [0.0, 0.0, 0.0]\n"
      "edges = [[0.0, 0.01, 0.0], [0.0, 0.0, 0.01]]\n";
  CHECK_THAT(refusal(small_slab("", symmetry + "wall_friction_angle = 30.0\n")),
             Contains("walls.toml") && Contains("[boundaries #1] wall_friction_angle") &&
                 Contains("kind = \"symmetry\"") && Contains("frictional"));
  for (const std::string key : {"velocity = [0.0, 1.0, 0.0]\nend = 1.0\n", "removed_at = 0.5\n", "end = 1.0\n"})
    CHECK_THAT(refusal(small_slab("", symmetry + key)),
               Contains("walls.toml") && Contains("[boundaries #1] ") && Contains(key.substr(0, key.find(' '))) &&
                   Contains("symmetry plane stays"));
  CHECK(refusal(small_slab("", symmetry)).empty());
  // Its images reflect one coordinate: a plane normal to no axis is refused.
  const std::string slanted = "[[boundaries]]\nshape = \"rectangle\"\nkind = \"symmetry\"\ncorner = [0.0, 0.0, 0.0]\n"
                              "edges = [[0.0, 0.01, 0.0], [0.01, 0.0, 0.01]]\n";
  CHECK_THAT(refusal(small_slab("", slanted)),
             Contains("walls.toml") && Contains("[boundaries #1] kind") && Contains("normal to x, y or z"));
}

TEST_CASE(
    "a moving wall of space carries its ghosts by v dt each step over its interval; removed, no soil feels "
    "it",
    "[walls-3d]") {
  // The plate holds the slab's released side and slides in its own plane, up (+y) and across (+z),
  // from 0 to 10 ms, stands, and is removed at 15 ms. (A wall moving away from the soil would drag
  // it: the mirror keeps the soil's normal velocity relative to the wall at the wall, as in 2D.)
  const Vec3 v{0.0, 0.1, 0.02};
  const double end = 0.01, removed_at = 0.015;
  const Scene3 s = parse_scene_3d(
      small_slab("gravity = 9.81", kPlate + "velocity = [0.0, 0.1, 0.02]\nend = 0.01\nremoved_at = 0.015\n"),
      "moving-plate.toml");
  const std::size_t plate = wall_named(s, "plate");
  ParticlesOf<3> p = build_particles_3d(s);
  set_geostatic_state_3d(p, s);
  const ParticlesOf<3> before = p;
  const SolverSetupOf<3> setup = make_solver_setup(s);
  WorkspaceOf<3> work(setup, p);
  std::vector<double> plate_force_x;  // F_x on the plate at each step (N)
  work.sampling.sampler = [&](const StepSampleOf<3>& sample) {
    plate_force_x.push_back(
        boundary_forces(sample.particles, sample.neighbours, sample.momentum, s.geometry.walls.size())[plate]
            .x);
  };
  work.sampling.due = true;
  const auto& model = std::get<LinearElastic>(s.material);
  const double dt = 1e-4, mass = 2000.0 * 0.004 * 0.004 * 0.004;
  std::size_t plate_ghosts = 0;
  double worst = 0.0;  // the largest distance of a ghost from where the closed form puts it (m)
  for (int k = 0; k < 200; ++k) {
    advance(model, setup, p, work, dt);
    const double t = (k + 1) * dt, moved = std::min(t, end);
    plate_ghosts = 0;
    for (std::size_t g = 0; g < p.image_begin - p.soil_count; ++g) {  // the lattice ghosts (not the soil's images)
      const std::size_t b = p.soil_count + g;
      const bool on_plate = static_cast<std::size_t>(p.wall_id[g]) == plate;
      const Vec3 expected = before.position(b) + (on_plate ? moved : 0.0) * v;
      worst = std::max(worst, norm(p.position(b) - expected));
      plate_ghosts += on_plate;
      // (The step that ends on `end` or `removed_at` is left out: the run's time is a sum of steps.)
      const double expected_mass = on_plate && t > removed_at ? 0.0 : mass;
      if (std::abs(t - removed_at) > 1e-9 && p.mass[b] != Approx(expected_mass).margin(1e-18))
        FAIL("ghost " << b << " at t = " << t << ": mass " << p.mass[b]);
      const Vec3 vw{p.wall_vx[g], p.wall_vy[g], p.wall_vz[g]};
      if (std::abs(t - end) > 1e-9 && !(vw == (on_plate && t < end ? v : Vec3{})))
        FAIL("ghost " << b << " at t = " << t << ": wall velocity");
    }
  }
  REQUIRE(plate_ghosts > 0);
  CHECK(worst < 1e-14);  // 200 additions of v dt: round-off only
  // The soil leans on the plate while it stands (the K0 thrust pushes it along −x), and not at all
  // once its ghosts have no mass: every pair term carries the ghost's mass.
  REQUIRE(plate_force_x.size() == 200);
  INFO("F_x on the plate at 12 ms: " << plate_force_x[120] << " N");
  CHECK(plate_force_x[120] < -1e-3);  // t = 12 ms: still there
  for (std::size_t k = 151; k < 200; ++k) CHECK(plate_force_x[k] == 0.0);
  CHECK(work.health.guard_corrections == 0);
}

TEST_CASE("the wall guard of space follows a moving plane and drops a removed one", "[walls-3d]") {
  // A floor y = 0 (the soil above) rising at 0.5 m/s for 1 s, removed at 2 s.
  PlaneGuard guard;
  guard.add(rectangle_wall({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}, "floor"), 0.01,
            WallMotionOf<3>{.removed_at = 2.0, .velocity = {0.0, 0.5, 0.0}, .start = 0.0, .end = 1.0});
  ParticlesOf<3> p;
  p.resize(1, 0);
  p.x[0] = 0.5, p.z[0] = 0.5;
  // At 0.5 s the floor is at y = 0.25 and rises at 0.5 m/s: a particle 5 mm below it, rising
  // slower, is put back on it with the floor's normal velocity.
  p.y[0] = 0.245, p.vx[0] = 0.1, p.vy[0] = 0.2;
  CHECK(guard.apply(p, 0.5).count == 1);
  CHECK(p.y[0] == Approx(0.25));
  CHECK(p.vy[0] == Approx(0.5));
  CHECK(p.vx[0] == 0.1);
  // At 1.5 s it stands at 0.5: one rising away from it keeps its velocity.
  p.y[0] = 0.495, p.vy[0] = 0.2;
  CHECK(guard.apply(p, 1.5).count == 1);
  CHECK(p.y[0] == Approx(0.5));
  CHECK(p.vy[0] == 0.2);
  // Where it stood at t = 0 it no longer guards, and once removed not at all.
  p.y[0] = -0.005;
  CHECK(guard.apply(p, 1.5).count == 0);
  p.y[0] = 0.495;
  CHECK(guard.apply(p, 2.0).count == 0);
}

TEST_CASE("the wall guard of space tells a particle put back past a floor's edge from one on it",
          "[walls-3d]") {
  // The floor y = 0 over the unit square, guarded 1 cm deep: a particle 1 mm below it over the
  // square, one 1 mm below its plane 5 mm beyond the edge x = 1 (soil that ran off it), one 2 cm
  // beyond (out of reach).
  PlaneGuard guard;
  guard.add(rectangle_wall({0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}, "floor"), 0.01);
  ParticlesOf<3> p;
  p.resize(3, 0);
  p.x = {0.5, 1.005, 1.02}, p.y = {-0.001, -0.001, -0.001}, p.z = {0.5, 0.5, 0.5};
  const GuardPushes pushed = guard.apply(p, 0.0);
  CHECK(pushed.count == 2);
  CHECK(pushed.past_edge == 1);
  CHECK(p.y[2] == -0.001);
}

TEST_CASE(
    "the slab's gate rises at lift_speed, its ghosts at v t, until its foot passes H + 2h + dp, then goes",
    "[walls-3d]") {
  const double v = 1.0, dx = 0.004;
  const std::vector<std::string> overrides = {
      "scene.particle_spacing=0.004", "scene.slab_thickness=0.008", "scene.wall_withdrawal=\"lift\"",
      "scene.lift_speed=1.0",         "scene.end_time=0.1",         "scene.stop_at_rest=false"};
  const Scene3 s = load_scene_3d(kSlab, overrides);
  const Geometry3& g = s.geometry;
  const Wall3& gate = g.walls[wall_named(s, "removable_wall")];
  // Its foot rises from the floor −Δp/2 to H + 2h + Δp: by H + 2h + 3Δp/2 at v.
  const double clear = (g.column_height + 2.0 * g.smoothing_length() + 1.5 * dx) / v;
  CHECK(gate.motion.velocity == Vec3{0.0, v, 0.0});
  CHECK(gate.motion.start == 0.0);
  CHECK(gate.motion.end == Approx(clear).epsilon(1e-12));
  CHECK(gate.motion.removed_at == gate.motion.end);
  CHECK(gate.plane.inward.x == Approx(1.0));
  Collapse3 collapse(s);
  const ParticlesOf<3> before = collapse.particles();
  const std::size_t gate_id = wall_named(s, "removable_wall");
  double worst = 0.0;
  std::size_t gate_ghosts = 0, massless_after_clear = 0, steps_after_clear = 0;
  const RunStatistics run = collapse.run(
      ThreadTuner(1, false), [](const ParticlesOf<3>&, double) {},
      [&](double t, std::size_t) {
        const ParticlesOf<3>& p = collapse.particles();
        gate_ghosts = 0;
        for (std::size_t k = 0; k < p.boundary_count(); ++k) {
          if (static_cast<std::size_t>(p.wall_id[k]) != gate_id) continue;
          const std::size_t b = p.soil_count + k;
          ++gate_ghosts;
          worst = std::max(worst, std::abs(p.y[b] - (before.y[b] + v * std::min(t, gate.motion.end))));
          worst = std::max({worst, std::abs(p.x[b] - before.x[b]), std::abs(p.z[b] - before.z[b])});
          if (t >= gate.motion.removed_at) massless_after_clear += p.mass[b] == 0.0;
        }
        if (t >= gate.motion.removed_at) steps_after_clear += gate_ghosts;
      });
  CHECK(run.end_time == Approx(0.1));
  REQUIRE(gate_ghosts > 0);
  CHECK(worst < 1e-12);
  CHECK(steps_after_clear > 0);
  CHECK(massless_after_clear == steps_after_clear);
  CHECK(run.guard_corrections == 0);
  // The soil left through the gate's opening: a particle beyond x = −Δp/2.
  const ParticlesOf<3>& p = collapse.particles();
  CHECK(*std::min_element(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(p.soil_count)) < -0.5 * dx);
}

TEST_CASE("the slab's gate as a [[boundaries]] rectangle is the gate of wall_withdrawal = \"lift\"",
          "[walls-3d]") {
  // At 4 mm (h = 5.2 mm) the gate spans y = −2 mm … H + 2h + Δp/2 = 0.0744 m and clears after
  // (H + 2h + 3Δp/2)/v = 0.0764 s at 1 m/s.
  const std::vector<std::string> common = {"scene.particle_spacing=0.004", "scene.slab_thickness=0.008"};
  std::vector<std::string> lift = common;
  lift.push_back("scene.wall_withdrawal=\"lift\"");
  lift.push_back("scene.lift_speed=1.0");
  const Scene3 shorthand = load_scene_3d(kSlab, lift);
  std::ifstream in(kSlab);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const Scene3 data = parse_scene_3d(text + R"(
[[boundaries]]
shape = "rectangle"
name = "gate"
kind = "free-slip"
corner = [-0.002, -0.002, 0.0]
edges = [[0.0, 0.0744, 0.0], [0.0, 0.0, 0.008]]
velocity = [0.0, 1.0, 0.0]
end = 0.0764
removed_at = 0.0764
)",
                                     kSlab, common);
  const ParticlesOf<3> a = build_particles_3d(shorthand), b = build_particles_3d(data);
  REQUIRE(a.size() == b.size());
  CHECK(a.x == b.x);
  CHECK(a.y == b.y);
  CHECK(a.z == b.z);
  CHECK(a.wall_nx == b.wall_nx);
  CHECK(a.image_sign_z == b.image_sign_z);
}

namespace {

/// A block on a plane inclined at θ about z (gravity along −y), built by hand as build_particles_3d
/// builds a scene's: the soil the lattice nodes of a 2 cm × 1 cm block (along × normal) from 3 cm
/// up the slope, half a spacing above it, 4 mm thick along z; the ghosts the lattice nodes behind
/// the plane (geometry/planar_ghosts.h). The scene gives the material, the numerics and gravity.
struct Incline {
  Scene3 scene;
  PlanarWall plane;
  Vec3 along, normal;  ///< up the slope, and into the soil
  ParticlesOf<3> particles;
  SolverSetupOf<3> setup;
};

Incline incline(double theta_deg, WallKind kind, double friction_angle, double gravity, bool one_particle) {
  const double dx = 0.001, theta = theta_deg * std::numbers::pi / 180.0;
  const Scene3 scene = parse_scene_3d(R"(
[scene]
dimension = 3
column_width = 0.02
column_height = 0.02
slab_thickness = 0.004
particle_spacing = 0.001
smoothing_ratio = 1.3
end_time = 0.05
wall_withdrawal = "instant"
gravity = )" + std::to_string(gravity) + "\n" +
                                          fixtures::kLinearElasticToml,
                                      "incline.toml");
  const Vec3 t{std::cos(theta), std::sin(theta), 0.0}, n{-t.y, t.x, 0.0};
  // Edges a up the slope and b along −z: a × b = n.
  const PlanarWall plane =
      rectangle_wall(0.02 * Vec3{0.0, 0.0, 1.0} - 0.01 * t, 0.12 * t, {0.0, 0.0, -0.04}, "incline");
  const Lattice3 lattice{{0.5 * dx, 0.5 * dx, 0.5 * dx}, dx};
  std::vector<Vec3> soil;
  if (one_particle) {
    soil = {0.5 * dx * n + Vec3{0.0, 0.0, 0.0005}};  // on the soil's lattice line of the wall
  } else {
    const auto at = [&](double a, double above) {
      return a * Vec2{t.x, t.y} + (above + 0.5 * dx) * Vec2{n.x, n.y};
    };
    soil = lattice_nodes_inside(
        make_extrusion({at(0.03, 0.0), at(0.05, 0.0), at(0.05, 0.01), at(0.03, 0.01)}, 0.0, 0.004, "block"),
        lattice);
  }
  const std::vector<PlanarWall> planes{plane};
  const int layers = scene.geometry.boundary_layers;
  const std::vector<GhostPoint3> ghosts = planar_ghost_points(planes, lattice, layers);
  const double rho = 2000.0;
  ParticlesOf<3> p;
  p.resize(soil.size(), ghosts.size());
  for (std::size_t i = 0; i < soil.size(); ++i) {
    p.x[i] = p.x0[i] = soil[i].x, p.y[i] = p.y0[i] = soil[i].y, p.z[i] = p.z0[i] = soil[i].z;
  }
  Wall plane_wall;  // μ by the 2D wall's one formula (stages/boundaries.h)
  plane_wall.kind = kind, plane_wall.friction_angle = friction_angle;
  for (std::size_t k = 0; k < ghosts.size(); ++k) {
    const std::size_t b = soil.size() + k;
    p.x[b] = ghosts[k].position.x, p.y[b] = ghosts[k].position.y, p.z[b] = ghosts[k].position.z;
    p.boundary_kind[k] = kind;
    p.wall_nx[k] = n.x, p.wall_ny[k] = n.y, p.wall_nz[k] = n.z;
    p.wall_friction[k] = wall_friction_coefficient(plane_wall);
    p.wall_stick[k] = kind == WallKind::NoSlip ? 1.0 : 0.0;
  }
  std::fill(p.density.begin(), p.density.end(), rho);
  std::fill(p.mass.begin(), p.mass.end(), rho * dx * dx * dx);
  SolverSetupOf<3> setup = make_solver_setup(scene);
  setup.guard = PlaneGuard{};
  setup.guard.add(plane, layers * dx);
  setup.walls = {};
  setup.symmetry_planes = {};  // the incline alone: none of the scene's planes
  setup.domain = {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};
  return {scene, plane, t, n, std::move(p), std::move(setup)};
}

struct Motion {
  double along, normal, across;  ///< mean velocity up the slope, away from it, along z (m/s)
  double deepest;                ///< largest distance of a soil particle behind the plane (m, ≤ 0: none)
  std::size_t guard_corrections;
};

Motion run_incline(Incline& c, double end_time) {
  ParticlesOf<3>& p = c.particles;
  WorkspaceOf<3> work(c.setup, p);
  const double dt = c.setup.initial_time_step();
  const auto& model = std::get<LinearElastic>(c.scene.material);
  const int steps = static_cast<int>(std::ceil(end_time / dt));
  for (int k = 0; k < steps; ++k) advance(model, c.setup, p, work, dt);
  Motion m{0.0, 0.0, 0.0, -1.0, work.health.guard_corrections};
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const Vec3 v = p.velocity(i);
    m.along += dot(v, c.along), m.normal += dot(v, c.normal), m.across += v.z;
    m.deepest = std::max(m.deepest, -c.plane.height_above(p.position(i)));
  }
  const auto n = static_cast<double>(p.soil_count);
  m.along /= n, m.normal /= n, m.across /= n;
  return m;
}

}  // namespace

TEST_CASE(
    "a particle gliding on an inclined free-slip plane keeps its tangential velocity; a no-slip one brakes "
    "it",
    "[walls-3d]") {
  // One soil particle half a spacing above a plane at 30°, moving along it at 0.1 m/s (up the slope
  // and across it), no gravity. Its only neighbours are ghosts; free slip gives them its own
  // tangential velocity, so the velocity gradient, its stress and the viscosity vanish: nothing
  // acts on it. (The ghosts start with the velocity their wall gives them, as the 2D test's.)
  const auto glide = [](WallKind kind) {
    Incline c = incline(30.0, kind, 0.0, 0.0, true);
    ParticlesOf<3>& p = c.particles;
    REQUIRE(p.soil_count == 1);
    const Vec3 v0 = 0.08 * c.along + 0.06 * Vec3{0.0, 0.0, 1.0};
    p.vx[0] = v0.x, p.vy[0] = v0.y, p.vz[0] = v0.z;
    const double mirror = kind == WallKind::NoSlip ? -1.0 : 1.0;
    for (std::size_t b = p.soil_count; b < p.size(); ++b)
      p.vx[b] = mirror * v0.x, p.vy[b] = mirror * v0.y, p.vz[b] = mirror * v0.z;
    WorkspaceOf<3> work(c.setup, p);
    for (int k = 0; k < 100; ++k) advance(std::get<LinearElastic>(c.scene.material), c.setup, p, work, 1e-5);
    return p.velocity(0) - v0;
  };
  const Vec3 dv = glide(WallKind::FreeSlip);
  INFO("dv = (" << dv.x << ", " << dv.y << ", " << dv.z << ") m/s");
  CHECK(norm(dv) < 1e-10);  // round-off: 10⁻⁹ of its speed after 100 steps
  CHECK(norm(glide(WallKind::NoSlip)) > 0.01);
}

TEST_CASE(
    "a block on an inclined plane: free slip at g sin(theta), held by friction delta > theta, and sliding at "
    "Coulomb's g (sin(theta) - tan(delta) cos(theta)) for delta < theta",
    "[walls-3d]") {
  const double t_end = 0.05, g = 9.81, theta = 30.0 * std::numbers::pi / 180.0;
  const double mu = std::tan(15.0 * std::numbers::pi / 180.0);
  Incline free_case = incline(30.0, WallKind::FreeSlip, 0.0, g, false);
  REQUIRE(free_case.particles.soil_count > 500);
  const Motion free = run_incline(free_case, t_end);
  Incline held_case = incline(30.0, WallKind::Frictional, 45.0, g, false);
  const Motion held = run_incline(held_case, t_end);
  Incline sliding_case = incline(30.0, WallKind::Frictional, 15.0, g, false);
  const Motion sliding = run_incline(sliding_case, t_end);
  const double free_slip = -g * std::sin(theta) * t_end;                         // −0.245 m/s
  const double coulomb = -g * (std::sin(theta) - mu * std::cos(theta)) * t_end;  // −0.131 m/s
  INFO("free " << free.along << " m/s, held " << held.along << ", sliding " << sliding.along << " (free slip "
               << free_slip << ", Coulomb " << coulomb << ")");
  // The block is cut from the axis-aligned lattice (a staircase base over ghosts on the same
  // lattice, as the 2D test's, which measured 0.85 of g sin θ t in the plane); in space it measured
  // 0.98 (2026-12-05), within the band 0.9 … 1.05.
  CHECK(free.along < 0.9 * free_slip);
  CHECK(free.along > 1.05 * free_slip);
  CHECK(std::abs(held.along) < 0.05 * std::abs(free_slip));
  // Kinetic friction μσ'_n against the slip takes μ g cos θ t off the free-slip block's velocity:
  // measured 1.03 of it (the 2D test's 1.17), within 0.9 … 1.2; the block's own speed is Coulomb's
  // within 10 %.
  const double coulomb_loss = g * mu * std::cos(theta) * t_end;
  CHECK(sliding.along - free.along > 0.9 * coulomb_loss);
  CHECK(sliding.along - free.along < 1.2 * coulomb_loss);
  CHECK(sliding.along == Approx(coulomb).epsilon(0.1));
  for (const Motion& m : {free, held, sliding}) {
    CHECK(std::abs(m.normal) < 0.05 * std::abs(coulomb));  // held: no flight off, no sinking in
    CHECK(std::abs(m.across) < 0.05 * std::abs(coulomb));  // no drift across the slope
    CHECK(m.deepest < 0.0);
    CHECK(m.guard_corrections == 0);
  }
}
