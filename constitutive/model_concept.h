#pragma once
/// @file
/// The model interface, stated once: what the point driver, the CVODE reference and the SPH stress
/// stage call on a model (each is a template instantiated per model from one std::visit). A new
/// model that misses a member fails here, at the registration in material.h, not deep inside a
/// driver. (Issue #11 item 5: first step; model hooks for the initial state and the CVODE
/// hardening rate are still to come.)
#include <concepts>
#include <string_view>

#include "constitutive/elasticity.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/state.h"

namespace soilsph {

/// Every model: its parameters (with a validating reader), its name in input files, its
/// elasticity, and the stress update over a strain and a spin increment.
template <class M>
concept ConstitutiveModel = requires(const M& model, const State& state, const Mat3& increment) {
  typename M::Params;
  { M::kName } -> std::convertible_to<std::string_view>;
  { model.params() } -> std::same_as<const typename M::Params&>;
  { model.elasticity() } -> std::same_as<const Elasticity&>;
  { model.update(state, increment, increment) } -> std::same_as<State>;
};

/// An elastic–plastic model: yield function, its gradient, the flow direction, the hardening term
/// of the consistency condition (0 for perfect plasticity), and the chosen integrator.
template <class M>
concept PlasticModel = ConstitutiveModel<M> && requires(const M& model, const Mat3& sigma, double pc) {
  { model.yield(sigma, pc) } -> std::convertible_to<double>;
  { model.normalized_yield(sigma, pc) } -> std::convertible_to<double>;
  { model.yield_gradient(sigma, pc) } -> std::convertible_to<Mat3>;
  { model.flow_direction(sigma, pc) } -> std::convertible_to<Mat3>;
  { model.hardening_modulus(sigma, pc) } -> std::convertible_to<double>;
  { model.integrator() } -> std::same_as<Integrator>;
};

}  // namespace soilsph
