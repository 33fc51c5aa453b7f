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

/// Q a Qᵀ for Q = [[c, s, 0], [−s, c, 0], [0, 0, 1]], a rotation about z: the in-plane block and
/// the (xz, yz) column and row rotate, a_zz stays (a need not be symmetric).
/// Written on scalars: GCC 12 builds the loop form's temporary Q a with 8-byte stores that 16-byte
/// loads read back (a store-forwarding stall, 30 % of this function's samples in the SPH step).
inline Mat3 rotate_about_z(const Mat3& a, double c, double s) {
  // Q a, rows 0 and 1 (row 2 is a's)
  const double b00 = c * a(0, 0) + s * a(1, 0), b01 = c * a(0, 1) + s * a(1, 1),
               b02 = c * a(0, 2) + s * a(1, 2);
  const double b10 = c * a(1, 0) - s * a(0, 0), b11 = c * a(1, 1) - s * a(0, 1),
               b12 = c * a(1, 2) - s * a(0, 2);
  Mat3 r;  // (Q a) Qᵀ
  r(0, 0) = c * b00 + s * b01, r(0, 1) = c * b01 - s * b00, r(0, 2) = b02;
  r(1, 0) = c * b10 + s * b11, r(1, 1) = c * b11 - s * b10, r(1, 2) = b12;
  r(2, 0) = c * a(2, 0) + s * a(2, 1), r(2, 1) = c * a(2, 1) - s * a(2, 0), r(2, 2) = a(2, 2);
  return r;
}

/// Rotates the stress of `state` with the spin increment; a zero spin costs one test.
/// A spin about z alone (plane strain: Δω_xy = −Δω_yx, every other entry 0) takes the closed form
/// of the same Cayley rotation, with a = ½Δω_xy:
///   Q = [[c, s, 0], [−s, c, 0], [0, 0, 1]],  c = (1 − a²)/(1 + a²),  s = 2a/(1 + a²),
/// instead of a 3×3 inverse and four general products (equal to round-off; tested).
inline State rotate_state(const State& state, const Mat3& spin_increment) {
  if (spin_increment.isZero(0.0)) return state;
  const Mat3& w = spin_increment;
  if (w(0, 2) == 0.0 && w(1, 2) == 0.0 && w(2, 0) == 0.0 && w(2, 1) == 0.0 && w(0, 0) == 0.0 &&
      w(1, 1) == 0.0 && w(2, 2) == 0.0 && w(1, 0) == -w(0, 1)) {
    const double a = 0.5 * w(0, 1), inv = 1.0 / (1.0 + a * a);
    const double c = (1.0 - a * a) * inv, s = 2.0 * a * inv;
    State rotated = state;
    rotated.stress = rotate_about_z(state.stress, c, s);
    return rotated;
  }
  const Mat3 Q = spin_rotation(spin_increment);
  State rotated = state;
  rotated.stress = Q * state.stress * Q.transpose();
  return rotated;
}

}  // namespace soilsph
