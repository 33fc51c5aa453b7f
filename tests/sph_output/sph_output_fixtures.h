#pragma once
// Synthetic particle sets for the output tests: every field holds distinct, reproducible values.
#include <cmath>
#include <vector>

#include "sph/output/frame_writer.h"

namespace soilsph::test {

/// n particles at time t with fields that differ between particles, fields and times.
struct SyntheticParticles {
  double time;
  std::vector<double> x, y, vx, vy, sxx, syy, szz, sxy, p, q, eps, density;
  std::vector<int> layer, material;

  SyntheticParticles(std::size_t n, double t) : time(t) {
    for (std::size_t i = 0; i < n; ++i) {
      const double k = static_cast<double>(i) + 10.0 * t;
      x.push_back(1e-3 * k);
      y.push_back(2e-3 * k + 1e-4);
      vx.push_back(-0.1 * k);
      vy.push_back(0.05 * std::sin(k));
      sxx.push_back(-1000.0 - k);
      syy.push_back(-2000.0 - 2 * k);
      szz.push_back(-1500.0 - 0.5 * k);
      sxy.push_back(10.0 * std::cos(k));
      p.push_back((1000.0 + k + 2000.0 + 2 * k + 1500.0 + 0.5 * k) / 3.0);
      q.push_back(300.0 + k / 7.0);
      eps.push_back(1e-3 * k * k);
      density.push_back(2000.0 + k);
      layer.push_back(static_cast<int>(i / 3));
      material.push_back(static_cast<int>(i % 2));
    }
  }
  sph::Frame frame() const { return {time, x, y, vx, vy, sxx, syy, szz, sxy, p, q, eps, density, layer, material}; }
};

}  // namespace soilsph::test
