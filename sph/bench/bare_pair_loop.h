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
#include <span>

namespace soilsph::sph {

/// Particle-steps per second of the bare loop on the points (x, y) with smoothing length h, on the
/// calling thread, timed over at least `min_seconds` (the median of the repeats).
double bare_pair_loop_rate(std::span<const double> x, std::span<const double> y, double h,
                           double min_seconds);

}  // namespace soilsph::sph
