#include "sph/geometry/read_particles.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string_view>
#include <utility>

#include "constitutive/parameters.h"
#include "sph/geometry/csv_fields.h"

namespace soilsph::sph {

std::vector<Region> read_particle_file(const std::string& path, const std::string& region_name, double dx,
                                       const std::string& scene_source,
                                       const std::vector<std::string>& materials) {
  std::ifstream in(path);
  if (!in) throw ParameterError(path + ": cannot read the particle file (" + region_name + " file)");
  const auto fail = [&](std::size_t line, const std::string& what) {
    throw ParameterError(path + ":" + std::to_string(line) + ": " + what);
  };
  std::string text;
  std::size_t line = 0;
  if (!std::getline(in, text)) fail(1, "empty file: expected the header x,y,region");
  ++line;
  if (csv_fields(text) != std::vector<std::string_view>{"x", "y", "region"})
    fail(line, "the header must be x,y,region (got \"" + std::string(trimmed(text)) + "\")");
  std::vector<Region> regions;
  std::vector<std::size_t> lines;  // each particle's line, for messages
  std::map<std::pair<long long, long long>, std::vector<std::pair<Vec2, std::size_t>>> cells;  // closeness
  while (std::getline(in, text)) {
    ++line;
    if (trimmed(text).empty()) continue;
    const std::vector<std::string_view> f = csv_fields(text);
    if (f.size() != 3) fail(line, "expected 3 fields x,y,region, got " + std::to_string(f.size()));
    double xy[2];
    for (int k = 0; k < 2; ++k) {
      const std::string s(f[static_cast<std::size_t>(k)]);
      std::size_t used = 0;
      try {
        xy[k] = std::stod(s, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (s.empty() || used != s.size()) fail(line, std::string(k ? "y" : "x") + " = \"" + s + "\" is not a number (m)");
      if (!std::isfinite(xy[k]) || std::abs(xy[k]) > 1e4)
        fail(line, std::string(k ? "y" : "x") + " = " + s + " m lies outside the domain (|x|, |y| <= 10000 m)");
    }
    std::string material(f[2]);
    if (material.empty() && materials.size() == 1) material = materials.front();
    if (std::find(materials.begin(), materials.end(), material) == materials.end())
      fail(line, "region = \"" + material + "\" names no [materials.NAME] table of " + scene_source +
                     (materials.size() == 1 ? " (leave it empty for the one material)" : ""));
    const Vec2 p{xy[0], xy[1]};
    const long long ci = std::llround(std::floor(p.x / dx)), cj = std::llround(std::floor(p.y / dx));
    for (long long i = ci - 1; i <= ci + 1; ++i)
      for (long long j = cj - 1; j <= cj + 1; ++j) {
        const auto it = cells.find({i, j});
        if (it == cells.end()) continue;
        for (const auto& [q, other] : it->second)
          if (norm(p - q) < 0.5 * dx)
            fail(line, "the particle at (" + format_number(p.x) + ", " + format_number(p.y) + ") m lies " +
                           format_number(norm(p - q)) + " m from that of line " + std::to_string(other) +
                           ", closer than half the [scene] particle_spacing of " + scene_source + " (" +
                           format_number(dx) + " m)");
      }
    cells[{ci, cj}].push_back({p, line});
    auto region = std::find_if(regions.begin(), regions.end(), [&](const Region& r) { return r.material == material; });
    if (region == regions.end()) {
      regions.push_back({Region::Shape::Particles, {}, material, region_name + " (" + path + ", " + material + ")", {}});
      region = regions.end() - 1;
    }
    region->particles.push_back(p);
  }
  if (regions.empty()) fail(line, "no particle (" + region_name + " file)");
  for (Region& r : regions) {  // the box of the particles' cells
    Vec2 lo = r.particles.front(), hi = lo;
    for (const Vec2& v : r.particles) lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    const double h = 0.5 * dx;
    r.outline = {{lo.x - h, lo.y - h}, {hi.x + h, lo.y - h}, {hi.x + h, hi.y + h}, {lo.x - h, hi.y + h}};
  }
  return regions;
}

}  // namespace soilsph::sph
