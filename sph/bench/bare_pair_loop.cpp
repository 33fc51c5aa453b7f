#include "sph/bench/bare_pair_loop.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <vector>

#include "sph/kernel.h"

namespace soilsph::sph {

namespace {
/// Index of σ_ab in the symmetric stress: xx, yy, xy in 2D; xx, yy, zz, xy, xz, yz in 3D.
template <int dim>
constexpr int sym(int a, int b) {
  if (a == b) return a;
  if constexpr (dim == 2) return 2;
  return a + b + 2;  // (0,1) → 3, (0,2) → 4, (1,2) → 5
}

template <int dim>
struct Fields {
  static constexpr int stresses = dim * (dim + 1) / 2;
  std::array<std::vector<double>, dim> v, a;
  std::array<std::vector<double>, stresses> s;
  std::array<std::vector<double>, dim * dim> L;
  std::vector<double> mass, density;
};

/// Calls f(cell) for the 3^dim cells around c.
template <int dim, class F>
void for_each_stencil_cell(const typename CellGrid<dim>::Cell& c, F&& f) {
  typename CellGrid<dim>::Cell n = c;
  if constexpr (dim == 2) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) n[0] = c[0] + dx, n[1] = c[1] + dy, f(n);
  } else {
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) n[0] = c[0] + dx, n[1] = c[1] + dy, n[2] = c[2] + dz, f(n);
  }
}

/// One bare step; returns a checksum so that the compiler cannot drop the work.
template <int dim>
double bare_step(const Coordinates<dim>& x, const CubicSplineKernel<dim>& W, CellGrid<dim>& cells, Fields<dim>& f) {
  const std::size_t n = x[0].size();
  const double support2 = W.support() * W.support();
  cells.build(x, W.support());
  const auto for_pairs = [&](std::size_t i, auto&& body) {
    for_each_stencil_cell<dim>(cells.cell_of_point(x, i), [&](const typename CellGrid<dim>::Cell& c) {
      for (const int j : cells.particles_in(c)) {
        const auto uj = static_cast<std::size_t>(j);
        std::array<double, dim> r;
        double r2 = 0.0;
        for (int d = 0; d < dim; ++d) r[d] = x[d][i] - x[d][uj], r2 += r[d] * r[d];
        if (uj == i || r2 >= support2) continue;
        const double g = W.value_and_gradient_factor(std::sqrt(r2)).dw_over_r;
        for (int d = 0; d < dim; ++d) r[d] *= g;
        body(uj, r);
      }
    });
  };
  for (std::size_t i = 0; i < n; ++i) {  // velocity gradient
    std::array<double, dim * dim> L{};
    for_pairs(i, [&](std::size_t j, const std::array<double, dim>& g) {
      const double v = f.mass[j] / f.density[j];
      for (int a = 0; a < dim; ++a) {
        const double dv = v * (f.v[a][j] - f.v[a][i]);
        for (int b = 0; b < dim; ++b) L[a * dim + b] += dv * g[b];
      }
    });
    for (int k = 0; k < dim * dim; ++k) f.L[k][i] = L[k];
  }
  double checksum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {  // stress divergence
    const double ri = 1.0 / (f.density[i] * f.density[i]);
    std::array<double, dim> acc{};
    for_pairs(i, [&](std::size_t j, const std::array<double, dim>& g) {
      const double rj = 1.0 / (f.density[j] * f.density[j]);
      std::array<double, Fields<dim>::stresses> t;
      for (int k = 0; k < Fields<dim>::stresses; ++k) t[k] = f.s[k][i] * ri + f.s[k][j] * rj;
      for (int a = 0; a < dim; ++a) {
        double ta = 0.0;
        for (int b = 0; b < dim; ++b) ta += t[sym<dim>(a, b)] * g[b];
        acc[a] += f.mass[j] * ta;
      }
    });
    for (int a = 0; a < dim; ++a) f.a[a][i] = acc[a], checksum += acc[a] + f.L[a * dim + a][i];
  }
  return checksum;
}
}  // namespace

template <int dim>
double bare_pair_loop_rate(const Coordinates<dim>& x, double h, double min_seconds) {
  using Clock = std::chrono::steady_clock;
  const std::size_t n = x[0].size();
  Fields<dim> f;
  for (auto& a : f.v) a.assign(n, 0.0);
  for (auto& a : f.a) a.assign(n, 0.0);
  for (auto& a : f.s) a.assign(n, 0.0);
  for (auto& a : f.L) a.assign(n, 0.0);
  f.mass.assign(n, 2.0e-3);
  f.density.assign(n, 2000.0);
  for (std::size_t i = 0; i < n; ++i) {  // smooth, non-trivial fields
    for (int a = 0; a < dim; ++a) f.v[a][i] = std::sin(100 * x[(a + 1) % dim][i]);
    for (int a = 0; a < dim; ++a) f.s[a][i] = -1e3 * (a + 1) * (1 + x[dim - 1 - a][i]);
    for (int k = dim; k < Fields<dim>::stresses; ++k) f.s[k][i] = 50 * x[0][i] * x[1][i];
  }
  const CubicSplineKernel<dim> W(h);
  CellGrid<dim> cells;
  std::vector<double> rates;
  volatile double sink = 0.0;
  const auto start = Clock::now();
  while (rates.size() < 3 || std::chrono::duration<double>(Clock::now() - start).count() < min_seconds) {
    const auto t0 = Clock::now();
    int steps = 0;
    double seconds = 0.0;
    while (seconds < 0.05) {  // one repeat: at least 50 ms
      sink = sink + bare_step<dim>(x, W, cells, f);
      ++steps;
      seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    rates.push_back(static_cast<double>(n) * steps / seconds);
  }
  std::nth_element(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2), rates.end());
  return rates[rates.size() / 2];
}

template double bare_pair_loop_rate<2>(const Coordinates<2>&, double, double);
template double bare_pair_loop_rate<3>(const Coordinates<3>&, double, double);

}  // namespace soilsph::sph
