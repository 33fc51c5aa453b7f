#include "sph/stages/momentum.h"

namespace soilsph::sph {
namespace {

/// The pair x_i − x_j and ∇_i W_ij of row position k (neighbour j), from the positions x and
/// dW/dr / r. Always inlined: called out of line, it keeps the 3D row sum from vectorising.
template <int dim>
[[gnu::always_inline]] inline std::pair<std::array<double, dim>, std::array<double, dim>> pair_vectors(
    const Coordinates<dim>& x, const PairRow::Row& row, std::size_t i, std::size_t k, std::size_t j) {
  std::array<double, dim> r, g;
  for (int d = 0; d < dim; ++d) r[d] = x[d][i] - x[d][j], g[d] = row.dw_over_r[k] * r[d];
  return {r, g};
}

/// The stress and viscosity terms of row i, summed with `omp simd` across the pairs. In the plane
/// on scalars: the form GCC vectorises two pairs to an SSE2 vector, whose order of summation the
/// plane's results are bit for bit tied to.
AccelerationOf<2> stress_and_viscosity_sum(const ParticlesOf<2>& p, const PairAccelerationOf<2>& term,
                                           const PairList<2>::Row& row, std::size_t i) {
  const double* const xs = p.x.data();
  const double* const ys = p.y.data();
  const double xi = xs[i], yi = ys[i];
  double ax = 0.0, ay = 0.0;
#pragma omp simd reduction(+ : ax, ay)
  for (std::size_t k = 0; k < row.size; ++k) {
    const auto j = static_cast<std::size_t>(row.j[k]);
    const double rx = xi - xs[j], ry = yi - ys[j], f = row.dw_over_r[k];
    const auto a = term.stress_and_viscosity(j, rx, ry, f * rx, f * ry);
    ax += a.x;
    ay += a.y;
  }
  return {ax, ay};
}
AccelerationOf<3> stress_and_viscosity_sum(const ParticlesOf<3>& p, const PairAccelerationOf<3>& term,
                                           const PairList<3>::Row& row, std::size_t i) {
  const Coordinates<3> x = p.coordinates();
  double ax = 0.0, ay = 0.0, az = 0.0;
#pragma omp simd reduction(+ : ax, ay, az)
  for (std::size_t k = 0; k < row.size; ++k) {
    const auto j = static_cast<std::size_t>(row.j[k]);
    const auto [r, g] = pair_vectors<3>(x, row, i, k, j);
    const AccelerationOf<3> a = term.stress_and_viscosity(j, r, g);
    ax += a[0];
    ay += a[1];
    az += a[2];
  }
  return {ax, ay, az};
}

template <int dim>
AccelerationOf<dim> acceleration_sum(const ParticlesOf<dim>& p, const PairList<dim>& nl, const MomentumParamsOf<dim>& m,
                                     std::size_t i, bool any_tension) {
  const PairAccelerationOf<dim> term(p, m, i);
  const typename PairList<dim>::Row row = nl.row(i);
  AccelerationOf<dim> a = stress_and_viscosity_sum(p, term, row, i);
  if (any_tension && term.artificial_stress_enabled()) {
    const Coordinates<dim> x = p.coordinates();
    for (std::size_t k = 0; k < row.size; ++k) {
      const auto j = static_cast<std::size_t>(row.j[k]);
      if (!term.has_artificial_stress(j)) continue;
      const auto g = pair_vectors<dim>(x, row, i, k, j).second;
      const AccelerationOf<dim> r = term.artificial_stress(j, row.w[k], g);
      for (int c = 0; c < dim; ++c) a[c] += r[c];
    }
  }
  if constexpr (dim == 2)
    return {a[0] + m.gravity.x, a[1] + m.gravity.y};
  else
    return {a[0] + m.gravity.x, a[1] + m.gravity.y, a[2] + m.gravity.z};
}

}  // namespace

AccelerationOf<2> acceleration_of(const ParticlesOf<2>& p, const PairList<2>& nl, const MomentumParamsOf<2>& m,
                                  std::size_t i, bool any_tension) {
  return acceleration_sum(p, nl, m, i, any_tension);
}
AccelerationOf<3> acceleration_of(const ParticlesOf<3>& p, const PairList<3>& nl, const MomentumParamsOf<3>& m,
                                  std::size_t i, bool any_tension) {
  return acceleration_sum(p, nl, m, i, any_tension);
}

}  // namespace soilsph::sph
