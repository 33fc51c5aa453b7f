#pragma once
// Every array a run's particles hold, for tests that compare two builds of a scene bit for bit
// (a symmetry wall against the free-slip wall it stands for).
#include <vector>

#include "sph/particles.h"

namespace soilsph::sph::test {

/// Every array of doubles of the particles, then the ids of their walls and their kinds.
template <int dim>
std::vector<std::vector<double>> arrays_of(const ParticlesOf<dim>& p) {
  std::vector<std::vector<double>> arrays;
  p.for_each_array([&](const char*, const std::vector<double>& a) { arrays.push_back(a); });
  p.for_each_wall_array([&](const std::vector<double>& a) { arrays.push_back(a); });
  arrays.emplace_back(p.wall_id.begin(), p.wall_id.end());
  std::vector<double> kinds;
  for (const BoundaryKind k : p.boundary_kind) kinds.push_back(static_cast<double>(static_cast<int>(k)));
  arrays.push_back(std::move(kinds));
  return arrays;
}

}  // namespace soilsph::sph::test
