#pragma once
/// @file
/// The Jaumann (spin) terms of the stress rate, eq 21/28: σ̇ ∋ σ^{αγ} ω̇^{βγ} + σ^{γβ} ω̇^{αγ} = (ω̇σ − σω̇)^{αβ},
/// with ω̇ = ½(∇v − ∇vᵀ) from eq 23.
///
/// Integrated over a step as the rotation σ ← Q σ Qᵀ with the Hughes–Winget (Cayley) rotation
/// Q = (I − ½Δω)⁻¹ (I + ½Δω), Δω = ω̇ Δt. Q is exactly orthogonal for a skew Δω, so a rigid spin keeps
/// every invariant (p, q, Lode angle) to round-off, and Q = I + Δω + O(Δω²) reproduces the paper's
/// first-order terms. (Hughes & Winget 1980, Int. J. Numer. Meth. Eng. 15:1862–1867.)
#include "constitutive/state.h"

#include <Eigen/LU>

namespace soilsph {

/// The incremental rotation for a skew spin increment Δω.
inline Mat3 spin_rotation(const Mat3& spin_increment) {
  const Mat3 half = 0.5 * spin_increment;
  return (Mat3::Identity() - half).inverse() * (Mat3::Identity() + half);
}

/// Rotates the tensorial parts of `state` with the spin increment; a zero spin costs one test.
inline State rotate_state(const State& state, const Mat3& spin_increment) {
  if (spin_increment.isZero(0.0)) return state;
  const Mat3 Q = spin_rotation(spin_increment);
  State rotated = state;
  rotated.stress = Q * state.stress * Q.transpose();
  rotated.plastic_strain = Q * state.plastic_strain * Q.transpose();
  return rotated;
}

}  // namespace soilsph
