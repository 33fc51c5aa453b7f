#include "sph/geometry/stl.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "constitutive/parameters.h"

namespace soilsph::sph {

namespace {
std::string point_text(Vec3 p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ", " + format_number(p.z) + ")";
}

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

/// Binary STL: an 80-byte header, a little-endian uint32 facet count, then per facet 12 float32
/// (normal, three vertices) and a uint16 attribute.
std::vector<Triangle> read_binary(const std::string& path, const std::string& bytes, double scale) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  std::vector<Triangle> triangles;
  triangles.reserve(count);
  for (std::size_t f = 0; f < count; ++f) {
    float v[12];
    std::memcpy(v, bytes.data() + 84 + 50 * f, sizeof v);
    Vec3 corner[3];
    for (int k = 0; k < 3; ++k) {
      corner[k] = {scale * v[3 + 3 * k], scale * v[4 + 3 * k], scale * v[5 + 3 * k]};
      if (!std::isfinite(corner[k].x) || !std::isfinite(corner[k].y) || !std::isfinite(corner[k].z))
        throw ParameterError(path + ": facet " + std::to_string(f + 1) + ": vertex " + std::to_string(k + 1) +
                             " is not finite");
    }
    triangles.push_back({corner[0], corner[1], corner[2]});
  }
  return triangles;
}

/// ASCII STL: solid NAME, then facets of seven lines (facet normal n n n / outer loop / vertex x y z
/// three times / endloop / endfacet), then endsolid.
std::vector<Triangle> read_ascii(const std::string& path, const std::string& bytes, double scale) {
  std::istringstream in(bytes);
  std::vector<Triangle> triangles;
  std::size_t line_number = 0;
  std::string line;
  const auto next = [&]() -> std::vector<std::string> {
    while (std::getline(in, line)) {
      ++line_number;
      if (auto w = words_of(line); !w.empty()) return w;
    }
    return {};
  };
  const auto fail = [&](const std::string& what) -> void {
    throw ParameterError(path + ":" + std::to_string(line_number) + ": " + what);
  };
  // The line's words must begin with those of `keywords` (e.g. "outer loop").
  const auto expect = [&](std::vector<std::string> w, const std::string& keywords, const std::string& facet) {
    const std::vector<std::string> wanted = words_of(keywords);
    if (w.size() < wanted.size() || !std::equal(wanted.begin(), wanted.end(), w.begin()))
      fail(facet + "expected \"" + keywords + "\", got \"" + line.substr(0, 80) + "\"");
    return w;
  };
  const auto number = [&](const std::string& word, const std::string& facet) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (error != std::errc() || end != word.data() + word.size())
      fail(facet + "\"" + word + "\" is not a number");
    if (!std::isfinite(value)) fail(facet + word + " is not finite");
    return value;
  };
  expect(next(), "solid", "");
  for (;;) {
    std::vector<std::string> w = next();
    if (w.empty()) fail("the file ends without \"endsolid\"");
    if (w[0] == "endsolid") break;
    const std::string facet = "facet " + std::to_string(triangles.size() + 1) + ": ";
    w = expect(w, "facet normal", facet);
    if (w.size() != 5) fail(facet + "expected \"facet normal nx ny nz\", got \"" + line.substr(0, 80) + "\"");
    expect(next(), "outer loop", facet);
    Vec3 corner[3];
    for (Vec3& c : corner) {
      w = expect(next(), "vertex", facet);
      if (w.size() != 4) fail(facet + "expected \"vertex x y z\", got \"" + line.substr(0, 80) + "\"");
      c = {scale * number(w[1], facet), scale * number(w[2], facet), scale * number(w[3], facet)};
    }
    expect(next(), "endloop", facet);
    expect(next(), "endfacet", facet);
    triangles.push_back({corner[0], corner[1], corner[2]});
  }
  return triangles;
}

/// Twice the signed area of the projection of (a, b, p) on the x–y plane, > 0 counter-clockwise,
/// computed from the lexicographically smaller end of [a, b] so that both facets of an edge get
/// exactly opposite values.
double edge_function(Vec3 a, Vec3 b, Vec3 p) {
  const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);
  const Vec3 u = swapped ? b : a, v = swapped ? a : b;
  const double w = (v.x - u.x) * (p.y - u.y) - (v.y - u.y) * (p.x - u.x);
  return swapped ? -w : w;
}

/// The tie rule for a point on the edge a → b of a counter-clockwise projection: the symbolic shift
/// (−ε, −ε²) puts it inside exactly when the edge points up, or left when horizontal.
bool tie_inside(Vec3 a, Vec3 b) {
  return b.y > a.y || (b.y == a.y && b.x < a.x);
}

bool covers(double w, Vec3 a, Vec3 b) {
  return w > 0.0 || (w == 0.0 && tie_inside(a, b));
}
}  // namespace

std::vector<Triangle> read_stl(const std::string& path, double scale) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParameterError(path + ": cannot read the STL file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Triangle> triangles;
  std::uint32_t count = 0;
  if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  const bool ascii = first != std::string::npos && bytes.compare(first, 5, "solid") == 0 &&
                     bytes.find('\0') == std::string::npos;  // binary headers may start with "solid" too
  if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<std::size_t>(count))
    triangles = read_binary(path, bytes, scale);
  else if (ascii)
    triangles = read_ascii(path, bytes, scale);
  else
    throw ParameterError(
        path + ": neither an ASCII STL (text starting with \"solid\") nor a binary STL (84 + 50 n bytes" +
        (bytes.size() >= 84 ? ", n = " + std::to_string(count) + " from its header" : std::string()) +
        ", but the file has " + std::to_string(bytes.size()) + " bytes)");
  if (triangles.empty()) throw ParameterError(path + ": no facet");
  return triangles;
}

StlSolid::StlSolid(std::vector<Triangle> triangles, const std::string& source)
    : triangles_(std::move(triangles)) {
  const auto fail = [&](std::size_t f, const std::string& what) {
    throw ParameterError(source + ": facet " + std::to_string(f + 1) + " " + what);
  };
  if (triangles_.size() < 4)
    throw ParameterError(source + ": " + std::to_string(triangles_.size()) +
                         " facets cannot enclose a solid (a closed surface needs at least 4)");
  bounds_ = {triangles_[0].a, triangles_[0].a};
  for (const Triangle& t : triangles_)
    for (Vec3 v : {t.a, t.b, t.c}) bounds_ = merged(bounds_, Box3{v, v});
  const double extent = std::max(norm(bounds_.hi - bounds_.lo), 1e-300);
  tolerance_ = 1e-9 * extent;
  // Closed: every edge (as exact vertex coordinates) belongs to exactly two facets.
  using Key = std::array<double, 3>;
  std::map<std::pair<Key, Key>, std::vector<std::size_t>> edges;
  for (std::size_t f = 0; f < triangles_.size(); ++f) {
    const Triangle& t = triangles_[f];
    if (norm(cross(t.b - t.a, t.c - t.a)) <= 1e-14 * extent * extent)
      fail(f, "has zero area (corners " + point_text(t.a) + ", " + point_text(t.b) + ", " + point_text(t.c) +
                  ")");
    const Vec3 corners[3] = {t.a, t.b, t.c};
    for (int k = 0; k < 3; ++k) {
      Key u{corners[k].x, corners[k].y, corners[k].z},
          v{corners[(k + 1) % 3].x, corners[(k + 1) % 3].y, corners[(k + 1) % 3].z};
      if (v < u) std::swap(u, v);
      edges[{u, v}].push_back(f);
    }
  }
  for (const auto& [edge, facets] : edges)
    if (facets.size() != 2)
      fail(facets.front(), "has the edge " + point_text({edge.first[0], edge.first[1], edge.first[2]}) +
                               " – " + point_text({edge.second[0], edge.second[1], edge.second[2]}) +
                               " shared by " + std::to_string(facets.size() - 1) +
                               " other facets (a closed surface shares each edge with exactly one)");
  // An x–y grid of about √n × √n bins.
  const auto n = static_cast<double>(triangles_.size());
  bins_x_ = bins_y_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(n)), 1, 512);
  bin_dx_ = std::max(bounds_.hi.x - bounds_.lo.x, tolerance_) / static_cast<double>(bins_x_);
  bin_dy_ = std::max(bounds_.hi.y - bounds_.lo.y, tolerance_) / static_cast<double>(bins_y_);
  bin_.assign(bins_x_ * bins_y_, {});
  for (std::size_t f = 0; f < triangles_.size(); ++f) {
    const Triangle& t = triangles_[f];
    const double x0 = std::min({t.a.x, t.b.x, t.c.x}) - tolerance_,
                 x1 = std::max({t.a.x, t.b.x, t.c.x}) + tolerance_;
    const double y0 = std::min({t.a.y, t.b.y, t.c.y}) - tolerance_,
                 y1 = std::max({t.a.y, t.b.y, t.c.y}) + tolerance_;
    const std::size_t lo = bin_of(x0, y0), hi = bin_of(x1, y1);
    for (std::size_t j = lo / bins_x_; j <= hi / bins_x_; ++j)
      for (std::size_t i = lo % bins_x_; i <= hi % bins_x_; ++i) bin_[i + bins_x_ * j].push_back(f);
  }
}

std::size_t StlSolid::bin_of(double x, double y) const {
  const auto clamp_index = [](double s, std::size_t count) {
    return static_cast<std::size_t>(std::clamp(std::floor(s), 0.0, static_cast<double>(count - 1)));
  };
  return clamp_index((x - bounds_.lo.x) / bin_dx_, bins_x_) +
         bins_x_ * clamp_index((y - bounds_.lo.y) / bin_dy_, bins_y_);
}

bool StlSolid::contains(Vec3 p) const {
  const Vec3 pad{tolerance_, tolerance_, tolerance_};
  if (!Box3{bounds_.lo - pad, bounds_.hi + pad}.contains(p)) return false;
  bool inside = false;
  for (const std::size_t f : bin_[bin_of(p.x, p.y)]) {
    Vec3 a = triangles_[f].a, b = triangles_[f].b, c = triangles_[f].c;
    const double area = edge_function(a, b, c);
    if (area == 0.0) continue;  // parallel to the ray: its neighbours decide
    if (area < 0.0) std::swap(b, c);
    const double wa = edge_function(b, c, p), wb = edge_function(c, a, p), wc = edge_function(a, b, p);
    if (!covers(wa, b, c) || !covers(wb, c, a) || !covers(wc, a, b)) continue;
    // Where the ray meets the facet's plane: the barycentric mean of the corners' z.
    const double z = (wa * a.z + wb * b.z + wc * c.z) / (wa + wb + wc);
    if (std::abs(z - p.z) <= tolerance_) return true;  // on the surface
    if (z > p.z) inside = !inside;
  }
  return inside;
}

double StlSolid::volume() const {
  double six = 0.0;
  for (const Triangle& t : triangles_) six += dot(t.a, cross(t.b, t.c));
  return std::abs(six) / 6.0;
}

StlSolid load_stl_solid(const std::string& path, double scale) {
  return StlSolid(read_stl(path, scale), path);
}

}  // namespace soilsph::sph
