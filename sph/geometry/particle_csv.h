#pragma once
/// @file
/// The rows of a particle CSV file of either dimension (geometry/read_particles.h for the plane,
/// read_particles_3d.h for space): the header `x,y,region` or `x,y,z,region`, then one particle a row,
/// each checked as it is read. Every error is a ParameterError naming the file and the line.
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "constitutive/parameters.h"
#include "sph/geometry/csv_fields.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// Calls on_particle(position, material) for each particle of `path`, in file order, once its row is
/// checked: dim + 1 fields; coordinates that parse, are finite and within 10⁴ m; a material among
/// `materials` (an empty one means the only material); no earlier particle closer than dx/2 (found
/// through cells of dx). A missing file, a wrong header or no particle at all is an error too.
/// `region_name` and `scene_source` (the scene file that reads the particles) name them in messages.
template <int dim, class OnParticle>
void read_particle_rows(const std::string& path, const std::string& region_name, double dx,
                        const std::string& scene_source, const std::vector<std::string>& materials,
                        OnParticle&& on_particle) {
  static constexpr const char* kAxis[3] = {"x", "y", "z"};
  const std::string header = dim == 2 ? "x,y,region" : "x,y,z,region";
  const std::string domain = dim == 2 ? "(|x|, |y| <= 10000 m)" : "(|x|, |y|, |z| <= 10000 m)";
  std::ifstream in(path);
  if (!in) throw ParameterError(path + ": cannot read the particle file (" + region_name + " file)");
  const auto fail = [&](std::size_t line, const std::string& what) {
    throw ParameterError(path + ":" + std::to_string(line) + ": " + what);
  };
  std::string text;
  std::size_t line = 0;
  if (!std::getline(in, text)) fail(1, "empty file: expected the header " + header);
  ++line;
  if (csv_fields(text) != csv_fields(header))
    fail(line, "the header must be " + header + " (got \"" + std::string(trimmed(text)) + "\")");
  using Cell = std::array<long long, dim>;
  std::map<Cell, std::vector<std::pair<Vec<dim>, std::size_t>>> cells;  // for the closeness check
  std::size_t particles = 0;
  while (std::getline(in, text)) {
    ++line;
    if (trimmed(text).empty()) continue;
    const std::vector<std::string_view> f = csv_fields(text);
    if (f.size() != dim + 1)
      fail(line,
           "expected " + std::to_string(dim + 1) + " fields " + header + ", got " + std::to_string(f.size()));
    std::array<double, dim> x;
    for (std::size_t k = 0; k < dim; ++k) {
      const std::string s(f[k]);
      std::size_t used = 0;
      try {
        x[k] = std::stod(s, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (s.empty() || used != s.size())
        fail(line, std::string(kAxis[k]) + " = \"" + s + "\" is not a number (m)");
      if (!std::isfinite(x[k]) || std::abs(x[k]) > 1e4)
        fail(line, std::string(kAxis[k]) + " = " + s + " m lies outside the domain " + domain);
    }
    std::string material(f[dim]);
    if (material.empty() && materials.size() == 1) material = materials.front();
    if (std::find(materials.begin(), materials.end(), material) == materials.end())
      fail(line, "region = \"" + material + "\" names no [materials.NAME] table of " + scene_source +
                     (materials.size() == 1 ? " (leave it empty for the one material)" : ""));
    Vec<dim> p;
    if constexpr (dim == 2)
      p = {x[0], x[1]};
    else
      p = {x[0], x[1], x[2]};
    Cell cell;
    for (std::size_t k = 0; k < dim; ++k) cell[k] = std::llround(std::floor(x[k] / dx));
    constexpr int kNeighbourCells = dim == 2 ? 9 : 27;
    for (int n = 0; n < kNeighbourCells; ++n) {  // the 3^dim cells around, the first axis outermost
      Cell near = cell;
      for (int k = dim - 1, digits = n; k >= 0; --k, digits /= 3) near[k] += digits % 3 - 1;
      const auto it = cells.find(near);
      if (it == cells.end()) continue;
      for (const auto& [q, other] : it->second)
        if (norm(p - q) < 0.5 * dx) {
          std::string at;
          for (std::size_t k = 0; k < dim; ++k) at += (k ? ", " : "") + format_number(x[k]);
          fail(line, "the particle at (" + at + ") m lies " + format_number(norm(p - q)) +
                         " m from that of line " + std::to_string(other) +
                         ", closer than half the [scene] particle_spacing of " + scene_source + " (" +
                         format_number(dx) + " m)");
        }
    }
    cells[cell].push_back({p, line});
    on_particle(p, material);
    ++particles;
  }
  if (particles == 0) fail(line, "no particle (" + region_name + " file)");
}

}  // namespace soilsph::sph
