#pragma once
/// @file
/// Duvaut–Lions viscoplasticity (Duvaut & Lions 1972; Simo & Hughes 1998, Computational Inelasticity
/// §2.7), for any model: the state X = (σ, p_c, accumulated plastic strains) relaxes towards the
/// rate-independent model's state X̄ with a relaxation time τ,
///   σ̇ = D : ε̇ − (σ − σ̄)/τ,   Ẋ_int = −(X_int − X̄_int)/τ,
/// so a stress beyond the yield surface is an overstress that decays in τ at rest and stands at
/// D : ε̇^vp τ under a steady strain rate. Backward Euler over Δt gives the update in closed form,
///   X_{n+1} = (X^trial + (Δt/τ) X̄_{n+1}) / (1 + Δt/τ),
/// X^trial the elastic trial from X_n (internal variables unchanged) and X̄_{n+1} the model's own
/// update from X_n over the same increment; τ → 0 is the model itself, τ → ∞ elasticity. Under a
/// steady shear rate γ̇ past yield its fixed point is exactly the continuum's overstress G γ̇ τ.
///
/// Why: a softening model without a material length (MCC on the dry side) localises into shear
/// bands as thin as the discretisation, so its SPH deposit moves with resolution. The relaxation
/// gives the bands a width (in waves about the P-wave speed times τ; in the slow flow of a collapse
/// set by the viscosity G τ), and the deposit converges (docs/validation/resolution.md).
/// It needs a time, so it acts in the SPH solver only: the material-point driver is
/// rate-independent and ignores it with a warning.
#include "constitutive/elasticity.h"
#include "constitutive/rotation.h"
#include "constitutive/state.h"

namespace soilsph {

/// The viscoplastic state after the increments (dε, dω) over dt from `start`, given the model's
/// rate-independent result `inviscid` for the same increments; dt_over_tau = Δt/τ > 0.
/// The elastic trial uses the model's elasticity as its returns do: the exact pressure after Δε_v
/// and the secant shear modulus, after the same rotation of the start.
inline State relax_viscoplastically(const Elasticity& elasticity, const State& start, const Mat3& strain_increment,
                                    const Mat3& spin_increment, const State& inviscid, double dt_over_tau) {
  const State rotated = rotate_state(start, spin_increment);
  const double p = mean_pressure(rotated.stress), d_eps_v = -strain_increment.trace();
  const double G = elasticity.secant(p, d_eps_v).G;
  const Mat3 trial = deviator(rotated.stress) + 2.0 * G * deviator(strain_increment) -
                     elasticity.pressure_after(p, d_eps_v) * identity3();
  const double r = dt_over_tau, weight = 1.0 / (1.0 + r);
  const auto relax = [&](double from, double to) { return (from + r * to) * weight; };
  State next = inviscid;
  next.stress = (trial + r * inviscid.stress) * weight;
  next.pc = relax(rotated.pc, inviscid.pc);
  next.plastic_shear_strain = relax(rotated.plastic_shear_strain, inviscid.plastic_shear_strain);
  next.plastic_dilation = relax(rotated.plastic_dilation, inviscid.plastic_dilation);
  next.plastic_multiplier = relax(0.0, inviscid.plastic_multiplier);
  return next;
}

}  // namespace soilsph
