#pragma once
/// @file
/// Upper bounds of material keys beyond which results lose meaning (docs/reference/materials.md).
#include "constitutive/parameters.h"

namespace soilsph::limits {

/// Largest stress, Pa, that an input (cohesion, pressure floor, initial stress) or a result may
/// hold: three times the pressure at the centre of the Earth (3.6e11 Pa), beyond any soil. A result
/// past it is an integration that ran away (e.g. explicit MCC hardening on huge strain increments).
inline constexpr double kMaxStress = 1e12;
/// Largest Young's modulus, Pa: five times the stiffest rock's (≈ 2e11 Pa). An update adds E·Δε to
/// stresses of order p in double precision, so above it the stress state drowns in round-off: with
/// E = 1e24 the explicit D-P undrained path returned p' = 0 instead of 100 kPa.
inline constexpr double kMaxYoungModulus = 1e12;
/// Smallest Young's modulus, Pa: 1 Pa, the smallest initial pressure an input may hold (the weight of
/// 0.1 mm of soil). Far below it an update's stiffness products reach the subnormal numbers: with
/// E = 1e-300 an undrained path lost its volume constraint (ε_v = 0.0016) and exited 0.
inline constexpr double kMinYoungModulus = 1.0;

/// Largest viscoplastic relaxation time, s: far beyond any run (τ → ∞ is elasticity).
inline constexpr double kMaxRelaxationTime = 1e3;

inline Range relaxation_time_range() { return Range::closed(0.0, kMaxRelaxationTime); }
inline Range young_modulus_range() { return Range::closed(kMinYoungModulus, kMaxYoungModulus); }
inline Range stress_range() { return Range::open_closed(0.0, kMaxStress); }  ///< (0, kMaxStress]

}  // namespace soilsph::limits
