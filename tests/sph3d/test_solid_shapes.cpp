// Soil shapes of space: extrusions, STL solids and imported particles, and the lattice fill, against
// counts and volumes in closed form.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <sstream>

#include "constitutive/parameters.h"
#include "sph/geometry/extrusion.h"
#include "sph/geometry/read_particles_3d.h"
#include "sph/geometry/solid.h"
#include "sph/geometry/stl.h"
#include "temp_dir.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

static_assert(SolidShape<Extrusion> && SolidShape<StlSolid>);

namespace {
/// The cube [0, a]³, each face two facets split along a diagonal, normals outward (right-handed).
std::vector<Triangle> cube(double a) {
  const auto corner = [a](int i) { return Vec3{a * (i & 1), a * ((i >> 1) & 1), a * ((i >> 2) & 1)}; };
  // Each face as four corner indices counter-clockwise seen from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Triangle> t;
  for (const auto& f : faces) {
    t.push_back({corner(f[0]), corner(f[1]), corner(f[2])});
    t.push_back({corner(f[0]), corner(f[2]), corner(f[3])});
  }
  return t;
}

/// A UV sphere of radius r about c: `rings` bands of latitude, `segments` of longitude, a vertex at
/// each pole (fans of facets meet there).
std::vector<Triangle> uv_sphere(Vec3 c, double r, int rings, int segments) {
  const auto at = [&](int i, int j) {
    const double theta = std::numbers::pi * i / rings, phi = 2.0 * std::numbers::pi * j / segments;
    if (i == 0) return c + Vec3{0.0, 0.0, r};
    if (i == rings) return c + Vec3{0.0, 0.0, -r};
    return c + Vec3{r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi),
                    r * std::cos(theta)};
  };
  std::vector<Triangle> t;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Vec3 a = at(i, j), b = at(i + 1, j), d = at(i, (j + 1) % segments),
                 e = at(i + 1, (j + 1) % segments);
      if (i > 0) t.push_back({a, b, d});
      if (i + 1 < rings) t.push_back({d, b, e});
    }
  return t;
}

/// The enclosed volume of a closed, outward-oriented triangulation by the divergence theorem.
double polyhedron_volume(const std::vector<Triangle>& t) {
  double six = 0.0;
  for (const Triangle& f : t)
    six += f.a.x * (f.b.y * f.c.z - f.b.z * f.c.y) - f.a.y * (f.b.x * f.c.z - f.b.z * f.c.x) +
           f.a.z * (f.b.x * f.c.y - f.b.y * f.c.x);
  return six / 6.0;
}

std::string ascii_stl(const std::vector<Triangle>& triangles) {
  std::ostringstream s;
  s.precision(17);
  s << "solid test shape\n";
  for (const Triangle& t : triangles) {
    s << "  facet normal 0 0 0\n    outer loop\n";
    for (Vec3 v : {t.a, t.b, t.c}) s << "      vertex " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    s << "    endloop\n  endfacet\n";
  }
  s << "endsolid test shape\n";
  return s.str();
}

std::string binary_stl(const std::vector<Triangle>& triangles) {
  std::string bytes(80, ' ');
  bytes.replace(0, 14, "solid (binary)");  // binary files may start with "solid" too
  const auto n = static_cast<std::uint32_t>(triangles.size());
  bytes.append(reinterpret_cast<const char*>(&n), 4);
  for (const Triangle& t : triangles) {
    const float v[12] = {0,
                         0,
                         0,
                         float(t.a.x),
                         float(t.a.y),
                         float(t.a.z),
                         float(t.b.x),
                         float(t.b.y),
                         float(t.b.z),
                         float(t.c.x),
                         float(t.c.y),
                         float(t.c.z)};
    bytes.append(reinterpret_cast<const char*>(v), sizeof v);
    bytes.append(2, '\0');
  }
  return bytes;
}
}  // namespace

TEST_CASE("lattice fill of an extruded L-shaped polygon: area / dx^2 nodes per plane", "[geometry3d]") {
  // Vertices on multiples of 1 cm, nodes at (i + 1/2) dx: no node on the outline, so the count is
  // exactly the area over dx² per plane: (4 x 1 + 1 x 2) cm² = 600 nodes of 1 mm, 5 planes in z.
  const std::vector<Vec2> outline{{0, 0}, {0.04, 0}, {0.04, 0.01}, {0.01, 0.01}, {0.01, 0.03}, {0, 0.03}};
  const Extrusion e = make_extrusion(outline, 0.0, 0.005, "case.toml: [[regions]] 1");
  const double dx = 0.001;
  const std::vector<Vec3> nodes =
      lattice_nodes_inside(e, {.origin = {dx / 2, dx / 2, dx / 2}, .spacing = dx});
  CHECK(nodes.size() == 600 * 5);
  // Nodes on the outline count (as 2D regions do): with the lattice on the vertices, (41 x 11 +
  // 11 x 20) per plane, 6 planes from z = 0 to 5 mm.
  CHECK(lattice_nodes_inside(e, {.origin = {0, 0, 0}, .spacing = dx}).size() == (41 * 11 + 11 * 20) * 6);
  CHECK(e.bounds().lo == Vec3{0, 0, 0});
  CHECK(e.bounds().hi == Vec3{0.04, 0.03, 0.005});
  // Clockwise outlines are the same shape.
  const Extrusion reversed = make_extrusion({outline.rbegin(), outline.rend()}, 0.0, 0.005, "r");
  CHECK(lattice_nodes_inside(reversed, {.origin = {dx / 2, dx / 2, dx / 2}, .spacing = dx}) == nodes);
}

TEST_CASE("an extrusion names what is wrong with it", "[geometry3d]") {
  CHECK_THROWS_WITH(make_extrusion({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.0, 1.0, "s.toml: [[regions]] 2"),
                    Contains("s.toml: [[regions]] 2: the outline is not simple"));
  CHECK_THROWS_WITH(make_extrusion({{0, 0}, {1, 0}, {0, 1}}, 1.0, 1.0, "s.toml: [[regions]] 2"),
                    Contains("z_max = 1 m must be finite and above z_min = 1 m"));
  CHECK_THROWS_WITH(make_extrusion({{0, 0}, {1, 0}, {0, NAN}}, 0.0, 1.0, "w"), Contains("not finite"));
}

TEST_CASE("STL cube: exactly (a/dx)^3 nodes, rays through the facets' shared diagonals included",
          "[geometry3d]") {
  // The lattice (i + 1/2) dx puts nodes with x = y (and y = z, x = z) on the diagonals that split
  // the faces into facets: the tie rule must count each such ray once.
  const double a = 0.02, dx = 0.001;
  const StlSolid solid(cube(a), "cube");
  const Lattice3 lattice{.origin = {dx / 2, dx / 2, dx / 2}, .spacing = dx};
  CHECK(lattice_nodes_inside(solid, lattice).size() == 20 * 20 * 20);
  CHECK(solid.volume() == Approx(a * a * a).epsilon(1e-12));
  // Shifted by a third of a spacing along each axis: no node on a face, still 20³.
  CHECK(lattice_nodes_inside(solid, {.origin = {dx / 3, dx / 3, dx / 3}, .spacing = dx}).size() ==
        20 * 20 * 20);
  // Inward-oriented facets enclose the same solid.
  std::vector<Triangle> flipped = cube(a);
  for (Triangle& t : flipped) std::swap(t.b, t.c);
  CHECK(lattice_nodes_inside(StlSolid(flipped, "flipped"), lattice).size() == 20 * 20 * 20);
  CHECK(solid.contains({0.01, 0.01, 0.01}));
  CHECK(!solid.contains({0.01, 0.01, 0.03}));
  CHECK(!solid.contains({0.01, 0.01, -0.001}));
  CHECK(solid.contains({0.01, 0.01, 0.02}));  // on the top face
}

TEST_CASE("STL sphere: the lattice count gives its volume", "[geometry3d]") {
  // R / dx = 20 about a node, so rays run through both poles (vertices where 48 facets meet).
  const double r = 0.02, dx = 0.001;
  const std::vector<Triangle> mesh = uv_sphere({0.0, 0.0, 0.0}, r, 24, 48);
  const StlSolid solid(mesh, "sphere");
  const std::size_t count = lattice_nodes_inside(solid, {.origin = {0, 0, 0}, .spacing = dx}).size();
  const double mesh_volume = polyhedron_volume(mesh);
  CHECK(solid.volume() == Approx(mesh_volume).epsilon(1e-12));
  // The inscribed polyhedron lies within 1 % of the sphere; the lattice count within 0.5 % of it
  // (the count's error is a surface effect, ~ (dx/R)^{3/2} for a smooth convex body).
  CHECK(mesh_volume == Approx(4.0 / 3.0 * std::numbers::pi * r * r * r).epsilon(0.01));
  CHECK(static_cast<double>(count) * dx * dx * dx == Approx(mesh_volume).epsilon(0.005));
  // The axis x = y = 0 through both poles: nodes strictly inside are in, beyond the poles out.
  CHECK(solid.contains({0, 0, 0.019}));
  CHECK(solid.contains({0, 0, -0.019}));
  CHECK(!solid.contains({0, 0, 0.021}));
  CHECK(!solid.contains({0, 0, -0.021}));
}

TEST_CASE("ASCII and binary STL read the same facets", "[geometry3d]") {
  const soilsph::test::TempDir dir("stl_read");
  const std::vector<Triangle> facets = cube(0.5);  // exact in float
  const std::vector<Triangle> ascii = read_stl(dir.write("cube.stl", ascii_stl(facets)));
  const std::vector<Triangle> binary = read_stl(dir.write("cube-binary.stl", binary_stl(facets)));
  REQUIRE(ascii.size() == 12);
  REQUIRE(binary.size() == 12);
  for (std::size_t f = 0; f < 12; ++f) {
    CHECK(ascii[f].a == facets[f].a);
    CHECK(ascii[f].c == facets[f].c);
    CHECK(binary[f].b == facets[f].b);
    CHECK(binary[f].c == facets[f].c);
  }
  // scale: millimetres to metres.
  CHECK(read_stl(dir.path / "cube.stl", 1e-3)[0].c.y == 0.5e-3);
  CHECK(load_stl_solid(dir.path / "cube-binary.stl").volume() == 0.125);
}

TEST_CASE("a bad STL file is named with its line and facet", "[geometry3d]") {
  const soilsph::test::TempDir dir("stl_errors");
  const std::string good = ascii_stl(cube(1.0));
  CHECK_THROWS_WITH(read_stl((dir.path / "missing.stl").string()),
                    Contains("missing.stl: cannot read the STL file"));
  CHECK_THROWS_WITH(read_stl(dir.write("junk.stl", "hello")), Contains("junk.stl: neither an ASCII STL"));
  std::string bad_number = good;
  bad_number.replace(bad_number.find("vertex 1 0 0"), 12, "vertex 1 x 0");
  CHECK_THROWS_WITH(read_stl(dir.write("number.stl", bad_number)),
                    Contains("number.stl:") && Contains(": facet ") && Contains("\"x\" is not a number"));
  // The second facet's first vertex line (line 1 + 7 + 3 = 11) lacks a coordinate.
  std::string short_vertex = good;
  const std::size_t second = short_vertex.find("vertex", short_vertex.find("endfacet"));
  short_vertex.replace(second, short_vertex.find('\n', second) - second, "vertex 0 0");
  CHECK_THROWS_WITH(read_stl(dir.write("short.stl", short_vertex)),
                    Contains("short.stl:11: facet 2: expected \"vertex x y z\""));
  CHECK_THROWS_WITH(read_stl(dir.write("unended.stl", good.substr(0, good.find("endsolid")))),
                    Contains("without \"endsolid\""));
  CHECK_THROWS_WITH(read_stl(dir.write("empty.stl", "solid nothing\nendsolid nothing\n")),
                    Contains("empty.stl: no facet"));
  std::string truncated = binary_stl(cube(1.0));
  truncated.resize(truncated.size() - 10);
  CHECK_THROWS_WITH(
      read_stl(dir.write("truncated.stl", truncated)),
      Contains("binary STL (84 + 50 n bytes, n = 12 from its header, but the file has 674 bytes)"));
  // An open surface: without its last facet, three edges have no partner.
  std::vector<Triangle> open = cube(1.0);
  open.pop_back();
  CHECK_THROWS_WITH(StlSolid(open, "open.stl"), Contains("open.stl: facet ") && Contains(" has the edge") &&
                                                    Contains("shared by 0 other facets"));
  std::vector<Triangle> sliver = cube(1.0);
  sliver[3].c = sliver[3].b;
  CHECK_THROWS_WITH(StlSolid(sliver, "sliver.stl"), Contains("sliver.stl: facet 4 has zero area"));
}

TEST_CASE("3D particles from CSV: regions by material, validated like the 2D reader", "[geometry3d]") {
  const soilsph::test::TempDir dir("particles_3d");
  const std::vector<std::string> materials{"sand", "clay"};
  const std::string path =
      dir.write("p.csv", "x,y,z,region\n0,0,0,sand\n0.01,0,0,clay\n\n0,0.01,0.02,sand\n");
  const std::vector<ParticleRegion3> regions =
      read_particle_file_3d(path, "[[regions]] 1", 0.01, "s.toml", materials);
  REQUIRE(regions.size() == 2);
  CHECK(regions[0].material == "sand");
  CHECK(regions[0].positions.size() == 2);
  CHECK(regions[0].positions[1] == Vec3{0, 0.01, 0.02});
  CHECK(regions[0].bounds.lo == Vec3{-0.005, -0.005, -0.005});
  CHECK(regions[0].bounds.hi == Vec3{0.005, 0.015, 0.025});
  CHECK(regions[1].material == "clay");
  const auto error = [&](const std::string& text) {
    try {
      read_particle_file_3d(dir.write("bad.csv", text), "[[regions]] 1", 0.01, "s.toml", materials);
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error("x,y,region\n"), Contains("bad.csv:1: the header must be x,y,z,region"));
  CHECK_THAT(error("x,y,z,region\n0,0,0\n"), Contains("bad.csv:2: expected 4 fields"));
  CHECK_THAT(error("x,y,z,region\n0,0,a,sand\n"), Contains("bad.csv:2: z = \"a\" is not a number"));
  CHECK_THAT(error("x,y,z,region\n0,0,1e5,sand\n"), Contains("lies outside the domain"));
  CHECK_THAT(error("x,y,z,region\n0,0,0,silt\n"),
             Contains("region = \"silt\" names no [materials.NAME] table of s.toml"));
  CHECK_THAT(
      error("x,y,z,region\n0,0,0,sand\n0.002,0.002,0.002,clay\n"),
      Contains("bad.csv:3: the particle at (0.002, 0.002, 0.002) m lies") &&
          Contains("from that of line 2, closer than half the [scene] particle_spacing of s.toml (0.01 m)"));
  CHECK_THAT(error("x,y,z,region\n"), Contains("bad.csv:1: no particle"));
}
