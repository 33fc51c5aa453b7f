#include "sph/bench/bare_pair_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "sph/kernel.h"
#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

namespace {
struct Fields {
  std::vector<double> vx, vy, sxx, syy, sxy, mass, density, lxx, lxy, lyx, lyy, ax, ay;
};

/// One bare step; returns a checksum so that the compiler cannot drop the work.
double bare_step(std::span<const double> x, std::span<const double> y, const CubicSpline& W, CellList& cells,
                 Fields& f) {
  const std::size_t n = x.size();
  const double support2 = W.support() * W.support();
  cells.build(x, y, W.support());
  const auto for_pairs = [&](std::size_t i, auto&& body) {
    const int cx = cells.cell_x(x[i]), cy = cells.cell_y(y[i]);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        for (const int j : cells.particles_in(cx + dx, cy + dy)) {
          const auto uj = static_cast<std::size_t>(j);
          const double rx = x[i] - x[uj], ry = y[i] - y[uj], r2 = rx * rx + ry * ry;
          if (uj == i || r2 >= support2) continue;
          const double g = W.value_and_gradient_factor(std::sqrt(r2)).dw_over_r;
          body(uj, g * rx, g * ry);
        }
  };
  for (std::size_t i = 0; i < n; ++i) {  // velocity gradient
    double lxx = 0, lxy = 0, lyx = 0, lyy = 0;
    for_pairs(i, [&](std::size_t j, double gx, double gy) {
      const double v = f.mass[j] / f.density[j], dvx = v * (f.vx[j] - f.vx[i]), dvy = v * (f.vy[j] - f.vy[i]);
      lxx += dvx * gx, lxy += dvx * gy, lyx += dvy * gx, lyy += dvy * gy;
    });
    f.lxx[i] = lxx, f.lxy[i] = lxy, f.lyx[i] = lyx, f.lyy[i] = lyy;
  }
  double checksum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {  // stress divergence
    const double ri = 1.0 / (f.density[i] * f.density[i]);
    double ax = 0, ay = 0;
    for_pairs(i, [&](std::size_t j, double gx, double gy) {
      const double rj = 1.0 / (f.density[j] * f.density[j]);
      const double txx = f.sxx[i] * ri + f.sxx[j] * rj, tyy = f.syy[i] * ri + f.syy[j] * rj,
                   txy = f.sxy[i] * ri + f.sxy[j] * rj;
      ax += f.mass[j] * (txx * gx + txy * gy), ay += f.mass[j] * (txy * gx + tyy * gy);
    });
    f.ax[i] = ax, f.ay[i] = ay;
    checksum += ax + ay + f.lxx[i] + f.lyy[i];
  }
  return checksum;
}
}  // namespace

double bare_pair_loop_rate(std::span<const double> x, std::span<const double> y, double h,
                           double min_seconds) {
  using Clock = std::chrono::steady_clock;
  const std::size_t n = x.size();
  Fields f;
  for (auto* a : {&f.vx, &f.vy, &f.sxx, &f.syy, &f.sxy, &f.lxx, &f.lxy, &f.lyx, &f.lyy, &f.ax, &f.ay})
    a->assign(n, 0.0);
  f.mass.assign(n, 2.0e-3);
  f.density.assign(n, 2000.0);
  for (std::size_t i = 0; i < n; ++i) {  // smooth, non-trivial fields
    f.vx[i] = std::sin(100 * y[i]), f.vy[i] = std::cos(100 * x[i]);
    f.sxx[i] = -1e3 * (1 + y[i]), f.syy[i] = -2e3 * (1 + x[i]), f.sxy[i] = 50 * x[i] * y[i];
  }
  const CubicSpline W(h);
  CellList cells;
  std::vector<double> rates;
  volatile double sink = 0.0;
  const auto start = Clock::now();
  while (rates.size() < 3 || std::chrono::duration<double>(Clock::now() - start).count() < min_seconds) {
    const auto t0 = Clock::now();
    int steps = 0;
    double seconds = 0.0;
    while (seconds < 0.05) {  // one repeat: at least 50 ms
      sink = sink + bare_step(x, y, W, cells, f);
      ++steps;
      seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }
    rates.push_back(static_cast<double>(n) * steps / seconds);
  }
  std::nth_element(rates.begin(), rates.begin() + static_cast<std::ptrdiff_t>(rates.size() / 2), rates.end());
  return rates[rates.size() / 2];
}

}  // namespace soilsph::sph
