#pragma once
/// @file
/// Leapfrog time integration (the paper's §4.1 note; Liu & Liu 2003) with a variable step:
/// velocities live at half steps, positions, density and stress at whole steps,
///   v^{n+½} = v^{n−½} + ½(Δt_{n−1} + Δt_n) a^n         (kick, a^n from σ^n, ρ^n, x^n)
///   ρ^{n+1} = ρ^n + Δt_n Dρ/Dt,  σ^{n+1} = update(σ^n, ε̇Δt_n, ω̇Δt_n)   (rates from v^{n+½} at x^n)
///   x^{n+1} = x^n + Δt_n v^{n+½}                         (drift)
/// The kick spans the time between the two half steps t^{n−½} and t^{n+½}, ½(Δt_{n−1} + Δt_n). The
/// run starts at rest with v^0 = 0 at t = 0; with Δt_{−1} = 0 the first kick is the half step
/// v^{½} = ½Δt_0 a^0 (a full Δt_0 a^0 would start the velocity half a step ahead). The rates over
/// [t^n, t^{n+1}] use the mid-step velocity, so the scheme is second order for positions and centred
/// for the stress increment. The solver (sph/solver.h) does kick and drift inside its fused loops.

namespace soilsph::sph {

/// The kick interval from v^{n−½} to v^{n+½}: ½(Δt_{n−1} + Δt_n); Δt_{−1} = 0 at the start.
inline double kick_interval(double previous_dt, double dt) {
  return 0.5 * (previous_dt + dt);
}

}  // namespace soilsph::sph
