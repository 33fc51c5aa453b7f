#pragma once
/// @file
/// The yardstick of `soilsph bench collapse`: a bare SPH pair loop, the least work any SPH step of
/// this kind must do, built into the same binary with the same compiler flags, so that the full
/// step's throughput can be quoted as a ratio measured in the same run (which survives a noisy,
/// shared machine, where absolute figures do not).
///
/// One bare step on fixed points: a cell list of side 2h, one pass for the velocity gradient
/// (Σ V_j (v_j − v_i) ⊗ ∇W) and one for the stress divergence (Σ m_j (σ_i/ρ_i² + σ_j/ρ_j²) ∇W),
/// the cubic spline evaluated on the fly; no boundaries, constitutive update, viscosity or output.
/// In 2D with 2 velocity and 3 stress components, in 3D with 3 and 6.
#include <span>

#include "sph/neighbours/cell_list.h"

namespace soilsph::sph {

/// Particle-steps per second of the bare loop on the points x (2 or 3 coordinate arrays) with
/// smoothing length h, on the calling thread, timed over at least `min_seconds` (the median of the
/// repeats).
template <int dim>
double bare_pair_loop_rate(const Coordinates<dim>& x, double h, double min_seconds);

/// The plane's loop on the points (x, y).
inline double bare_pair_loop_rate(std::span<const double> x, std::span<const double> y, double h,
                                  double min_seconds) {
  return bare_pair_loop_rate<2>({x, y}, h, min_seconds);
}

}  // namespace soilsph::sph
