#pragma once
/// @file
/// Driver sub-steps of a mixed-control increment (`--path-tolerance`).
///
/// Why: one mixed-control increment imposes a straight strain path on the strain-imposed components
/// and meets the imposed stresses only at its end; between the ends the free strains follow a
/// straight line too, so the stress-imposed components are not held inside the increment. CVODE holds
/// them throughout. The difference is a path error, O(Δε³) per increment and O(Δε²) over a path,
/// whatever the integrator: on the drained triaxial path of the stiff clay (K = (1+e0)p/κ from
/// 200 kPa) 2.5e-3 at 20 increments, above our goal of 1e-3.
///
/// What: the increment is done as m sub-steps of Δε_i/m on the strain-imposed components, each
/// meeting the imposed stresses interpolated linearly to its own end, σ*(j/m) = σ*_start +
/// (j/m)(σ*_end − σ*_start) (the linear load programme CVODE follows in pseudo-time). The path error
/// then falls like 1/m².
///
/// Error control by step doubling (Richardson): with e(m) ≈ C/m² the error of the m-sub-step result,
///   X(m) − X(2m) = e(2m) − e(m) ≈ −3 e(2m),   so   e(2m) ≈ |X(2m) − X(m)| / 3,
/// for X the effective stress (relative to max(‖σ'‖, ‖σ'_n‖, 1 Pa), Frobenius), the pore pressure
/// (same scale), p_c (relative) and the strain increment (relative to the strain reached on the
/// leg, Frobenius): every imposed and free component, so that the tolerance bounds the error of the
/// whole curve whichever components a leg imposes. (A leg that imposes every stress component has
/// its stresses fixed by the targets at both m and 2m: there only the strains tell the results
/// apart, and they are what grows without bound towards a limit state.) m doubles until that estimate of the
/// finer result is ≤ the tolerance; the finer result is accepted. The estimate includes the stress
/// integrator's own error over the sub-steps (it changes with m too), so the control is on the whole
/// increment. The next increment starts from the m that would just meet the tolerance, m' = ⌈m √(2
/// e(2m)/tol)⌉ (at least 1, at most 2m): neighbouring increments of a smooth path need about as many
/// sub-steps, and starting from there saves the doublings. The cost of an accepted increment is 3m sub-steps
/// (m and 2m) where 2m would do; a fixed m chosen from the tolerance would need the constant C in advance.
/// The output keeps one row per requested increment.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "constitutive/state.h"
#include "constitutive/voigt.h"
#include "verification/paths/load_path.h"

namespace soilsph::verification {

/// Sub-steps of one increment, and what the next increment should start from.
struct PathSubsteps {
  int next = 1;         ///< sub-steps to try first on the next increment (m of the pair m, 2m)
  long long total = 0;  ///< sub-steps of accepted results, over the run (for reports)
};

namespace detail {
/// The increment `leg` from `state` to the imposed stresses `target` (those at the increment's end)
/// done as `m` sub-steps by `solve(state, sub_leg, sub_target, strain_increment, u)` (one
/// mixed-control increment). Sets `strain_increment` to their sum and `u` to u at the end.
template <class Solve>
State substepped(const Solve& solve, const State& state, const Leg& leg, const Vec6& target, int m,
                 Vec6& strain_increment, double& u) {
  Leg sub = leg;
  sub.increment = leg.increment / m;
  const Vec6 start_target = target - leg.increment;  // used on the stress-imposed entries only
  State current = state;
  strain_increment = Vec6::Zero();
  for (int j = 1; j <= m; ++j) {
    const Vec6 sub_target =
        j == m ? target : Vec6(start_target + (static_cast<double>(j) / m) * leg.increment);
    Vec6 d;
    current = solve(current, sub, sub_target, d, u);
    strain_increment += d;
  }
  return current;
}

/// Frobenius norm of a Voigt strain (engineering shears) as the tensor's.
inline double strain_norm(const Vec6& strain) {
  const Mat3 e = strain_from_voigt(strain);
  return std::sqrt(ddot(e, e));
}

/// The step-doubling estimate e(2m) = |X(2m) − X(m)| / 3 (see the file comment), the largest over
/// the effective stress and pore pressure (relative to the stress scale), p_c (relative) and the
/// strain increment of every component (relative to the strain the leg has reached, `leg_strain` +
/// the fine increment, or to the increment itself at the leg's start). Imposed components agree
/// between the two results by construction; the free ones carry the error: the strains on a leg
/// whose every stress component is imposed, the stresses on one whose every strain is.
inline double doubling_estimate(const State& start, const Vec6& leg_strain, const State& coarse,
                                double u_coarse, const Vec6& coarse_strain, const State& fine, double u_fine,
                                const Vec6& fine_strain) {
  const double scale =
      std::max({std::sqrt(ddot(fine.stress, fine.stress)), std::sqrt(ddot(start.stress, start.stress)), 1.0});
  const Mat3 d = fine.stress - coarse.stress;
  double e = std::max(std::sqrt(ddot(d, d)), std::abs(u_fine - u_coarse)) / scale;
  if (fine.pc > 0.0) e = std::max(e, std::abs(fine.pc - coarse.pc) / fine.pc);
  const double strain_scale = std::max(strain_norm(leg_strain + fine_strain), strain_norm(fine_strain));
  if (strain_scale > 0.0) e = std::max(e, strain_norm(fine_strain - coarse_strain) / strain_scale);
  return e / 3.0;
}
}  // namespace detail

/// One increment with sub-steps controlled to `tolerance` (> 0) by step doubling, from m =
/// `substeps.next`; `leg_strain` is the strain (Voigt) the leg has reached before this increment, at most
/// `max_substeps` sub-steps (then the finest result is taken: the estimate is reported by nothing else, and
/// more sub-steps than that are a mistake of the tolerance).
template <class Solve>
State path_controlled_increment(const Solve& solve, const State& state, const Vec6& leg_strain,
                                const Leg& leg, const Vec6& target, double tolerance, int max_substeps,
                                PathSubsteps& substeps, Vec6& strain_increment, double& pore_pressure) {
  int m = std::clamp(substeps.next, 1, std::max(1, max_substeps / 2));
  Vec6 coarse_strain, fine_strain;
  double coarse_u = pore_pressure, fine_u = pore_pressure;
  State coarse = detail::substepped(solve, state, leg, target, m, coarse_strain, coarse_u);
  while (true) {
    fine_u = pore_pressure;
    State fine = detail::substepped(solve, state, leg, target, 2 * m, fine_strain, fine_u);
    const double estimate = detail::doubling_estimate(state, leg_strain, coarse, coarse_u, coarse_strain,
                                                      fine, fine_u, fine_strain);
    if (estimate <= tolerance || 4 * m > max_substeps) {
      // e ∝ 1/m²: the pair (m', 2m') with e(2m') = tol/2 has m' = m √(2 e(2m)/tol).
      const double wanted = m * std::sqrt(2.0 * estimate / tolerance);
      substeps.next = std::clamp(static_cast<int>(std::ceil(wanted)), 1, 2 * m);
      substeps.total += 2 * m;
      strain_increment = fine_strain;
      pore_pressure = fine_u;
      return fine;
    }
    m *= 2;  // the fine result becomes the coarse one of the next pair
    coarse = std::move(fine);
    coarse_strain = fine_strain;
    coarse_u = fine_u;
  }
}

}  // namespace soilsph::verification
