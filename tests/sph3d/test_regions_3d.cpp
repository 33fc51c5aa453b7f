// 3D scenes of [[regions]] (sph/read_regions_3d.h, geometry/regions_3d.h): each shape's lattice nodes
// against a count made here from its definition and against its volume, the first region listed
// winning an overlap, the refusals (empty regions, bad keys), the floor, [deposit], and the shipped
// two-soil cylinder's geostatic state against σ_v = −g Σ ρ_i h_i and each soil's K0.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "sph/collapse_3d.h"
#include "sph/initial_state_3d.h"
#include "sph/scene_3d.h"
#include "temp_dir.h"

using soilsph::ParameterError;
using namespace soilsph::sph;

namespace {

const std::string kTwoSoils = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/two-soil-cylinder-3d.toml";

/// [scene] and one [material] at Δp = 4 mm; the regions follow.
const std::string kHead = R"(
[scene]
dimension = 3
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.5
[initial]
lateral_stress_ratio = 0.5
[material]
model = "drucker-prager"
density = 2000.0
young_modulus = 5.0e6
poisson_ratio = 0.3
friction_angle = 35.0
cohesion = 0.0
dilatancy_angle = 0.0
)";

/// Two materials a and b of densities 2000 and 1500 kg/m³; the regions follow.
const std::string kTwoMaterialsHead = R"(
[scene]
dimension = 3
particle_spacing = 0.004
smoothing_ratio = 1.3
end_time = 0.5
[materials.a]
model = "linear-elastic"
density = 2000.0
young_modulus = 5.0e6
poisson_ratio = 0.25
[materials.b]
model = "linear-elastic"
density = 1500.0
young_modulus = 5.0e6
poisson_ratio = 0.375
)";

template <class F>
void require_refusal(F&& what, const std::vector<std::string>& words) {
  try {
    what();
    FAIL("no error");
  } catch (const ParameterError& e) {
    const std::string message = e.what();
    INFO(message);
    for (const std::string& w : words) CHECK(message.find(w) != std::string::npos);
  }
}

/// The soil particles of a scene read from text.
ParticlesOf<3> soil_of(const std::string& text, const std::string& source = "regions.toml") {
  return build_particles_3d(parse_scene_3d(text, source));
}

/// Nodes (i + ½, k + ½) (in spacings, from the axis) of a disc of radius n spacings over the part:
/// i, k over all (whole), k ≥ 0 (half), i, k ≥ 0 (quarter); counted here from the definition.
long long disc_nodes(int n, bool half, bool quarter) {
  long long count = 0;
  for (int i = -n - 1; i <= n; ++i)
    for (int k = -n - 1; k <= n; ++k) {
      if ((quarter && i < 0) || ((half || quarter) && k < 0)) continue;
      if ((i + 0.5) * (i + 0.5) + (k + 0.5) * (k + 0.5) <= double(n) * n) ++count;
    }
  return count;
}

}  // namespace

TEST_CASE("a box region holds one node per cell of its volume", "[regions3d]") {
  // Sides on cell edges (multiples of Δp with the default lattice origin (Δp/2, Δp/2, Δp/2)):
  // 0.04 × 0.02 × 0.012 m at 4 mm is 10 × 5 × 3 cells.
  const ParticlesOf<3> p = soil_of(kHead + R"(
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.04, 0.02, 0.012]
)");
  CHECK(p.soil_count == 150);
  const double dx = 0.004;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    CHECK(p.mass[i] == Approx(2000.0 * dx * dx * dx).epsilon(1e-14));  // ρ Δp³
    CHECK(p.material[i] == 0);
  }
}

TEST_CASE("a cylinder region holds the lattice nodes of its disc in every row, whole, half or quarter",
          "[regions3d]") {
  // r = 10 Δp, H = 5 Δp from a base centre on a cell edge, off the origin: 5 rows of the disc.
  for (const auto& [part, half, quarter, share] :
       {std::tuple{"whole", false, false, 1.0}, std::tuple{"half", true, false, 0.5},
        std::tuple{"quarter", false, true, 0.25}}) {
    SECTION(part) {
      const ParticlesOf<3> p = soil_of(kHead + R"(
[[regions]]
shape = "cylinder"
base_centre = [0.08, 0.0, -0.04]
radius = 0.04
height = 0.02
part = ")" + std::string(part) + "\"\n");
      const long long expected = 5 * disc_nodes(10, half, quarter);
      CHECK(static_cast<long long>(p.soil_count) == expected);
      // Against the volume: π r² H × share in cells, within the lattice's rim (about 2πr·H/Δp² × share / 2).
      const double cells = std::numbers::pi * 100.0 * 5.0 * share,
                   rim = 2.0 * std::numbers::pi * 10.0 * 5.0 * share;
      CHECK(std::abs(static_cast<double>(p.soil_count) - cells) < 0.5 * rim);
      for (std::size_t i = 0; i < p.soil_count; ++i) {
        const double x = p.x[i] - 0.08, z = p.z[i] + 0.04;
        CHECK(x * x + z * z <= 0.04 * 0.04 * (1 + 1e-9));
        if (quarter) CHECK(x > 0.0);
        if (half || quarter) CHECK(z > 0.0);
        CHECK(p.y[i] > 0.0);
        CHECK(p.y[i] < 0.02);
      }
    }
  }
}

TEST_CASE("an extrusion region holds the nodes of its polygon in every layer along z", "[regions3d]") {
  // The right triangle (0, 0), (10Δp, 0), (0, 10Δp): nodes (i + ½, j + ½) with i + j ≤ 9 (those on
  // the hypotenuse count as inside), 55 a layer; z from 0 to 5Δp: 5 layers. Its volume: 50 × 5 cells.
  const ParticlesOf<3> p = soil_of(kHead + R"(
[[regions]]
shape = "extrusion"
points = [[0.0, 0.0], [0.04, 0.0], [0.0, 0.04]]
z_min = 0.0
z_max = 0.02
)");
  CHECK(p.soil_count == 5 * 55);
  CHECK(std::abs(static_cast<double>(p.soil_count) - 250.0) < 0.15 * 250.0);
}

TEST_CASE("an STL region holds the nodes inside its closed surface, scaled from the file's units",
          "[regions3d]") {
  // The cube [0, 20]³ mm as 12 facets, in millimetres (scale = 0.001): 5³ nodes at 4 mm.
  const soilsph::test::TempDir dir("regions3d_stl");
  const double v[8][3] = {{0, 0, 0},  {20, 0, 0},  {20, 20, 0},  {0, 20, 0},
                          {0, 0, 20}, {20, 0, 20}, {20, 20, 20}, {0, 20, 20}};
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                            {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {0, 4, 7}, {0, 7, 3}};
  std::string stl = "solid cube\n";
  for (const auto& f : faces) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int c : f)
      stl += "   vertex " + std::to_string(v[c][0]) + " " + std::to_string(v[c][1]) + " " +
             std::to_string(v[c][2]) + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid cube\n";
  dir.write("cube.stl", stl);
  const std::string scene = dir.write("scene.toml", kHead + R"(
[[regions]]
shape = "stl"
file = "cube.stl"
scale = 0.001
)");
  const Scene3 s = load_scene_3d(scene);
  CHECK(build_particles_3d(s).soil_count == 125);
  // The file is recorded as an absolute path: the resolved scene reads back from anywhere.
  const Scene3 again = parse_scene_3d(scene_toml(s), "elsewhere/scene.toml");
  CHECK(build_particles_3d(again).soil_count == 125);
}

TEST_CASE("a particles region takes its file's particles, one region per material named", "[regions3d]") {
  const soilsph::test::TempDir dir("regions3d_particles");
  dir.write("soil.csv", "x,y,z,region\n0.002,0.002,0.002,a\n0.006,0.002,0.002,b\n0.002,0.006,0.002,a\n");
  const std::string scene = dir.write("scene.toml", kTwoMaterialsHead + R"(
[[regions]]
shape = "particles"
file = "soil.csv"
)");
  const Scene3 s = load_scene_3d(scene);
  REQUIRE(s.material_names == std::vector<std::string>{"a", "b"});
  const ParticlesOf<3> p = build_particles_3d(s);
  REQUIRE(p.soil_count == 3);
  // Ordered by material (a's two first, in file order), each with its own ρ Δp³.
  const double cell = 0.004 * 0.004 * 0.004;
  CHECK(p.material[0] == 0);
  CHECK(p.material[1] == 0);
  CHECK(p.material[2] == 1);
  CHECK(p.y[1] == 0.006);
  CHECK(p.x[2] == 0.006);
  CHECK(p.mass[0] == Approx(2000.0 * cell).epsilon(1e-14));
  CHECK(p.mass[2] == Approx(1500.0 * cell).epsilon(1e-14));
  require_refusal(
      [&] {
        (void)load_scene_3d(dir.write(
            "bad.toml", kTwoMaterialsHead +
                            "[[regions]]\nshape = \"particles\"\nfile = \"soil.csv\"\nmaterial = \"a\"\n"));
      },
      {"[regions #1]", "material"});
}

TEST_CASE("overlapping regions: a node belongs to the first region listed", "[regions3d]") {
  // Box a: 5 × 5 × 5 cells; box b: 10 × 5 × 5 cells, half of it over a's.
  const Scene3 s = parse_scene_3d(kTwoMaterialsHead + R"(
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.02, 0.02, 0.02]
material = "a"
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.04, 0.02, 0.02]
material = "b"
)",
                                  "overlap.toml");
  const ParticlesOf<3> p = build_particles_3d(s);
  CHECK(p.soil_count == 250);
  std::map<int, int> count;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    ++count[p.material[i]];
    CHECK(p.material[i] == (p.x[i] < 0.02 ? 0 : 1));
  }
  CHECK(count[0] == 125);
  CHECK(count[1] == 125);
}

TEST_CASE("a region that holds no node is an error naming it", "[regions3d]") {
  SECTION("covered by an earlier region") {
    require_refusal(
        [] {
          (void)soil_of(kHead + R"(
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.04, 0.04, 0.04]
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.02, 0.02, 0.02]
)");
        },
        {"regions.toml", "[regions #2]", "holds no particle", "particle_spacing"});
  }
  SECTION("thinner than a spacing between nodes") {
    require_refusal(
        [] {
          (void)soil_of(kHead + R"(
[[regions]]
shape = "cylinder"
base_centre = [0.0, 0.0, 0.0]
radius = 0.001
height = 0.02
)");
        },
        {"[regions #1]", "holds no particle"});
  }
}

TEST_CASE("every refusal of a 3D regions scene names its table and key", "[regions3d]") {
  const std::string box = "[[regions]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.04, 0.04, 0.04]\n";
  using Case = std::tuple<std::string, std::vector<std::string>>;  // appended text, words of the message
  const Case cases[] = {
      {"[[regions]]\nshape = \"sphere\"\n", {"[regions #1]", "shape"}},
      {"[[regions]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.041, 0.04, 0.04]\n",
       {"[regions #1]", "max", "cell edge"}},
      {"[[regions]]\nshape = \"box\"\nmin = [0.0, 0.0]\nmax = [0.04, 0.04, 0.04]\n",
       {"[regions #1]", "min", "[x, y, z]"}},
      {"[[regions]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.04, 0.04, 0.04]\nradius = 0.1\n",
       {"[regions #1]", "radius"}},
      {"[[regions]]\nshape = \"cylinder\"\nbase_centre = [0.0, 0.0, 0.0]\nradius = 0.04\nheight = 0.04\npart "
       "= \"third\"\n",
       {"[regions #1]", "part"}},
      {"[[regions]]\nshape = \"cylinder\"\nbase_centre = [0.0, 0.0, 0.0]\nradius = -0.04\nheight = 0.04\n",
       {"[regions #1]", "radius"}},
      {"[[regions]]\nshape = \"cylinder\"\nradius = 0.04\nheight = 0.04\n", {"[regions #1]", "base_centre"}},
      {"[[regions]]\nshape = \"extrusion\"\npoints = [[0.0, 0.0], [0.04, 0.0], [0.0, 0.04]]\nz_min = "
       "0.02\nz_max = 0.0\n",
       {"[regions #1]", "z_max"}},
      {"[[regions]]\nshape = \"extrusion\"\npoints = [[0.0, 0.0], [0.04, 0.0]]\nz_min = 0.0\nz_max = 0.02\n",
       {"[regions #1]", "points"}},
      {"[[regions]]\nshape = \"stl\"\nfile = \"missing.stl\"\n", {"missing.stl"}},
      {box + "material = \"clay\"\n", {"[regions #1]", "material"}},
  };
  for (const auto& [text, words] : cases) {
    SECTION(text) {
      require_refusal([&] { (void)soil_of(kHead + text); }, words);
    }
  }
  SECTION("the shorthands' keys and [[regions]] exclude each other") {
    require_refusal(
        [&] {
          (void)parse_scene_3d(kHead + box, "s.toml", std::vector<std::string>{"scene.column_radius=0.04"});
        },
        {"column_radius", "[[regions]]"});
  }
  SECTION("the floor may not cut the soil, and lies on a cell edge") {
    require_refusal(
        [&] {
          (void)parse_scene_3d(kHead + box, "s.toml", std::vector<std::string>{"scene.floor_level=0.004"});
        },
        {"floor_level", "lowest soil cell"});
    require_refusal(
        [&] {
          (void)parse_scene_3d(kHead + box, "s.toml", std::vector<std::string>{"scene.floor_level=-0.001"});
        },
        {"floor_level", "cell edge"});
  }
  SECTION("[deposit] keys") {
    require_refusal(
        [&] {
          (void)parse_scene_3d(kHead + box + "[deposit]\naxis = [0.0, 0.0]\nazimuth_span = 400.0\n",
                               "s.toml");
        },
        {"[deposit]", "azimuth_span"});
    require_refusal([&] { (void)parse_scene_3d(kHead + box + "[deposit]\nazimuth_span = 90.0\n", "s.toml"); },
                    {"[deposit]", "axis"});
  }
}

TEST_CASE(
    "a regions scene stands on a no-slip floor under its soil, and measures its deposit only with [deposit]",
    "[regions3d]") {
  const std::string box = "[[regions]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.04, 0.04, 0.04]\n";
  const Scene3 s = parse_scene_3d(kHead + box, "s.toml");
  const Geometry3& g = s.geometry;
  CHECK(g.shape == Geometry3::Shape::Regions);
  CHECK(g.floor_level == 0.0);  // the cell edge under the lowest row (y = Δp/2)
  CHECK(g.surface_level == 0.04);
  CHECK(g.base_level == Approx(0.002).epsilon(1e-12));
  REQUIRE(g.walls.size() == 1);
  CHECK(g.walls[0].label == "floor");
  CHECK(g.walls[0].kind == WallKind::NoSlip);
  CHECK(g.walls[0].plane.inward.y == Approx(1.0));
  // The default margin: 2 × 1.24 H + 4 Δp beyond the soil, H the soil's height between its rows.
  const double margin = 2.0 * 1.24 * 0.036 + 4.0 * 0.004;
  const Box3 floor_box = [&] {
    Box3 b{g.walls[0].plane.at(g.walls[0].plane.outline[0]),
           g.walls[0].plane.at(g.walls[0].plane.outline[0])};
    for (const Vec2& q : g.walls[0].plane.outline)
      b = merged(b, Box3{g.walls[0].plane.at(q), g.walls[0].plane.at(q)});
    return b;
  }();
  CHECK(floor_box.lo.x == Approx(-margin).epsilon(1e-12));
  CHECK(floor_box.hi.z == Approx(0.04 + margin).epsilon(1e-12));
  CHECK(!g.deposit_measured);
  // The floor's ghosts lie below it, each marked no-slip.
  const ParticlesOf<3> p = build_particles_3d(s);
  for (std::size_t k = 0; k < p.boundary_count(); ++k) {
    CHECK(p.y[p.soil_count + k] < 0.0);
    CHECK(p.boundary_kind[k] == WallKind::NoSlip);
  }
  const Scene3 measured =
      parse_scene_3d(kHead + box + "[deposit]\naxis = [0.02, 0.02]\nazimuth_span = 90.0\n", "s.toml");
  CHECK(measured.geometry.deposit_measured);
  CHECK(measured.geometry.deposit_axis.point == Vec3{0.02, 0.0, 0.02});
  CHECK(measured.geometry.azimuth_span_deg == 90.0);
  // The resolved scene reads back to the same scene.
  const Scene3 again = parse_scene_3d(scene_toml(measured), "scene.toml");
  CHECK(scene_toml(again) == scene_toml(measured));
}

TEST_CASE("local-surface: each particle hangs from the top of its own lattice column", "[regions3d]") {
  // A step: a box 0 ≤ x ≤ 0.02 up to 0.04 and 0.02 ≤ x ≤ 0.04 up to 0.02, one material.
  const Scene3 s = parse_scene_3d(kHead + R"(
[[regions]]
shape = "box"
min = [0.0, 0.0, 0.0]
max = [0.02, 0.04, 0.008]
[[regions]]
shape = "box"
min = [0.02, 0.0, 0.0]
max = [0.04, 0.02, 0.008]
)",
                                  "step.toml", std::vector<std::string>{"initial.stress=\"local-surface\""});
  ParticlesOf<3> p = build_particles_3d(s);
  set_geostatic_state_3d(p, s);
  const double rho_g = 2000.0 * 9.81;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const double surface = p.x[i] < 0.02 ? 0.04 : 0.02;  // the column's top node + Δp/2
    CHECK(p.syy[i] == Approx(-rho_g * (surface - p.y[i])).epsilon(1e-12));
    CHECK(p.sxx[i] == Approx(0.5 * p.syy[i]).epsilon(1e-12));
    CHECK(p.szz[i] == Approx(0.5 * p.syy[i]).epsilon(1e-12));
  }
}

TEST_CASE("the shipped two-soil cylinder: counts, masses, materials and the layered geostatic stress",
          "[regions3d]") {
  const Scene3 s = load_scene_3d(kTwoSoils);
  REQUIRE(s.material_names == std::vector<std::string>{"lower", "upper"});
  CHECK(s.region_material == std::vector<int>{0, 1});
  Collapse3 collapse(s);
  const ParticlesOf<3>& p = collapse.particles();
  // r0 = 10 Δp: 6 rows of the lower soil and 4 of the upper, each the disc's nodes; about π r0² H/Δp³.
  const long long disc = disc_nodes(10, false, false);
  CHECK(static_cast<long long>(p.soil_count) == 10 * disc);
  CHECK(std::abs(static_cast<double>(p.soil_count) - std::numbers::pi * 100.0 * 10.0) <
        0.1 * std::numbers::pi * 1000.0);
  const double dx = 0.005, g = 9.81, rho_lower = 2000.0, rho_upper = 1600.0;
  const double k0_lower = 0.3333333333333333 / (1.0 - 0.3333333333333333), k0_upper = 0.375 / 0.625;
  std::map<int, long long> count;
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const bool lower = p.y[i] < 0.03;
    ++count[p.material[i]];
    CHECK(p.material[i] == (lower ? 0 : 1));
    const double rho = lower ? rho_lower : rho_upper, k0 = lower ? k0_lower : k0_upper;
    CHECK(p.mass[i] == Approx(rho * dx * dx * dx).epsilon(1e-14));
    // σ_v = −g Σ ρ_i h_i below the flat top y = 5 cm: the upper soil's 2 cm over the lower soil.
    const double sigma_v =
        lower ? -g * (rho_upper * 0.02 + rho_lower * (0.03 - p.y[i])) : -g * rho_upper * (0.05 - p.y[i]);
    CHECK(p.syy[i] == Approx(sigma_v).epsilon(1e-9));
    CHECK(p.sxx[i] == Approx(k0 * sigma_v).epsilon(1e-9));
    CHECK(p.szz[i] == Approx(k0 * sigma_v).epsilon(1e-9));
    CHECK(p.sxy[i] == 0.0);
    CHECK(p.sxz[i] == 0.0);
    CHECK(p.syz[i] == 0.0);
  }
  CHECK(count[0] == 6 * disc);
  CHECK(count[1] == 4 * disc);
  CHECK(s.geometry.deposit_measured);
  CHECK(s.geometry.azimuth_span_deg == 360.0);
  CHECK(s.geometry.floor_level == 0.0);
}
