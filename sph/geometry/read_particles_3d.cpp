#include "sph/geometry/read_particles_3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string_view>
#include <utility>

#include "constitutive/parameters.h"
#include "sph/geometry/csv_fields.h"

namespace soilsph::sph {

namespace {
using Cell = std::array<long long, 3>;
Cell cell_of(Vec3 p, double dx) {
  return {std::llround(std::floor(p.x / dx)), std::llround(std::floor(p.y / dx)),
          std::llround(std::floor(p.z / dx))};
}
}  // namespace

std::vector<ParticleRegion3> read_particle_file_3d(const std::string& path, const std::string& region_name,
                                                   double dx, const std::string& scene_source,
                                                   const std::vector<std::string>& materials) {
  std::ifstream in(path);
  if (!in) throw ParameterError(path + ": cannot read the particle file (" + region_name + " file)");
  const auto fail = [&](std::size_t line, const std::string& what) {
    throw ParameterError(path + ":" + std::to_string(line) + ": " + what);
  };
  std::string text;
  std::size_t line = 0;
  if (!std::getline(in, text)) fail(1, "empty file: expected the header x,y,z,region");
  ++line;
  if (csv_fields(text) != std::vector<std::string_view>{"x", "y", "z", "region"})
    fail(line, "the header must be x,y,z,region (got \"" + std::string(trimmed(text)) + "\")");
  std::vector<ParticleRegion3> regions;
  std::map<Cell, std::vector<std::pair<Vec3, std::size_t>>> cells;  // for the closeness check
  static constexpr const char* kAxis[3] = {"x", "y", "z"};
  while (std::getline(in, text)) {
    ++line;
    if (trimmed(text).empty()) continue;
    const std::vector<std::string_view> f = csv_fields(text);
    if (f.size() != 4) fail(line, "expected 4 fields x,y,z,region, got " + std::to_string(f.size()));
    double xyz[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string s(f[k]);
      std::size_t used = 0;
      try {
        xyz[k] = std::stod(s, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (s.empty() || used != s.size())
        fail(line, std::string(kAxis[k]) + " = \"" + s + "\" is not a number (m)");
      if (!std::isfinite(xyz[k]) || std::abs(xyz[k]) > 1e4)
        fail(line,
             std::string(kAxis[k]) + " = " + s + " m lies outside the domain (|x|, |y|, |z| <= 10000 m)");
    }
    std::string material(f[3]);
    if (material.empty() && materials.size() == 1) material = materials.front();
    if (std::find(materials.begin(), materials.end(), material) == materials.end())
      fail(line, "region = \"" + material + "\" names no [materials.NAME] table of " + scene_source +
                     (materials.size() == 1 ? " (leave it empty for the one material)" : ""));
    const Vec3 p{xyz[0], xyz[1], xyz[2]};
    const Cell c = cell_of(p, dx);
    for (long long i = c[0] - 1; i <= c[0] + 1; ++i)
      for (long long j = c[1] - 1; j <= c[1] + 1; ++j)
        for (long long k = c[2] - 1; k <= c[2] + 1; ++k) {
          const auto it = cells.find({i, j, k});
          if (it == cells.end()) continue;
          for (const auto& [q, other] : it->second)
            if (norm(p - q) < 0.5 * dx)
              fail(line, "the particle at (" + format_number(p.x) + ", " + format_number(p.y) + ", " +
                             format_number(p.z) + ") m lies " + format_number(norm(p - q)) +
                             " m from that of line " + std::to_string(other) +
                             ", closer than half the [scene] particle_spacing of " + scene_source + " (" +
                             format_number(dx) + " m)");
        }
    cells[c].push_back({p, line});
    auto region = std::find_if(regions.begin(), regions.end(),
                               [&](const ParticleRegion3& r) { return r.material == material; });
    if (region == regions.end()) {
      regions.push_back({.material = material,
                         .name = region_name + " (" + path + ", " + material + ")",
                         .positions = {},
                         .bounds = {p, p}});
      region = regions.end() - 1;
    }
    region->positions.push_back(p);
    region->bounds = merged(region->bounds, Box3{p, p});
  }
  if (regions.empty()) fail(line, "no particle (" + region_name + " file)");
  const Vec3 half{0.5 * dx, 0.5 * dx, 0.5 * dx};
  for (ParticleRegion3& r : regions) r.bounds = {r.bounds.lo - half, r.bounds.hi + half};
  return regions;
}

}  // namespace soilsph::sph
