#pragma once
/// @file
/// Whether an initial state (a geostatic column, a programme's start) is admissible for a model: on
/// or inside its yield surface, to 1e-9 of the yield function's terms (normalized_yield).
///
/// A state that is isotropic to round-off is tested as exactly isotropic. σ = v I (the geostatic
/// stress at K0 = 1) has a deviator σ − tr(σ)/3 I of a few ulps, not zero, so √J2 ≈ 3e-16 |v|; a cone
/// more slender than that, a cohesionless D-P with φ ~ 1e-29° (found by the input fuzzer), would
/// then refuse the one K0 its cone holds. Snapping a deviator below 64 ε |p| moves the normalized
/// yield value by about 64 ε |p| over the terms' size, far below the 1e-9 tolerance unless the
/// surface is that slender, so no other verdict changes.
#include <cmath>
#include <limits>

#include "constitutive/state.h"
#include "constitutive/tensor.h"

namespace soilsph {

template <class Model>
bool admissible_state(const Model& model, const State& s) {
  if constexpr (requires { model.normalized_yield(s.stress, s.pc); }) {
    const double p = mean_pressure(s.stress);
    const bool isotropic = std::sqrt(second_deviatoric_invariant(s.stress)) <=
                           64.0 * std::numeric_limits<double>::epsilon() * std::abs(p);
    return model.normalized_yield(isotropic ? Mat3(-p * Mat3::Identity()) : s.stress, s.pc) <= 1e-9;
  } else {
    return true;  // no yield surface (linear elasticity)
  }
}

}  // namespace soilsph
