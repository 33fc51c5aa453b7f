#pragma once
/// @file
/// The model interface, stated once: everything that code outside a model's own files (the point
/// driver and programmes, the CVODE reference, the SPH stress stage and initial state, the stress
/// test, `soilsph material`) calls on a model. Each caller is a template instantiated per model from
/// one std::visit, so a hook is a direct call, never a virtual one or a lookup by name. A model that
/// misses a member fails here, at the registration in material.h, not deep inside a driver; and the
/// drivers, the SPH solver, the stress test and the apps need not ask which model they have. (What
/// is model-specific by nature stays so: a closed form describes one model, and the verification
/// report writes the constants of MCC's yield ellipse and void ratio for its plots.)
///
/// Optional hooks, found by `requires` where they are used and absent from the concepts: a dilatancy
/// cut-off (models/dilatancy_cutoff.h), the reasons a soil may loosen without bound
/// (models/loosening.h), and a multi-surface model's planes one by one, `plane_count()` and
/// `planes(σ)`, with which the CVODE reference combines an edge's or corner's flows by Koiter's rule
/// (verification/reference/yield_surfaces.h; Mohr–Coulomb).
///
/// Adding a model: a folder's worth of files in constitutive/ (its header and source in models/, its
/// implicit return in integrators/), then one line in material.h's Material variant and its name
/// in read_material (material.cpp).
#include <concepts>
#include <string>
#include <string_view>

#include "constitutive/elasticity.h"
#include "constitutive/failure_line.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/state.h"

namespace soilsph {

/// Every model: its parameters (validated by the constructor, read from TOML by Params::read with the
/// same ranges and defaults), its name in input files, its elasticity, the stress update over a
/// strain and a spin increment, its initial hardening state from an OCR (0 for models without
/// one, `kHasPreconsolidation` false), and a description of its derived constants.
template <class M>
concept ConstitutiveModel = requires(const M& model, const State& state, const Mat3& increment, double ocr) {
  typename M::Params;
  { M::kName } -> std::convertible_to<std::string_view>;
  { M::kHasPreconsolidation } -> std::convertible_to<bool>;
  { model.params() } -> std::same_as<const typename M::Params&>;
  { model.elasticity() } -> std::same_as<const Elasticity&>;
  { model.update(state, increment, increment) } -> std::same_as<State>;
  { model.initial_preconsolidation(increment, ocr, ocr) } -> std::convertible_to<double>;
  { model.describe_constants() } -> std::convertible_to<std::string>;
};

/// An elastic–plastic model: yield function, its gradient, the flow direction, the hardening term
/// of the consistency condition (0 for perfect plasticity), the rate of the hardening variable for
/// a plastic flow λ̇ n_g (the CVODE reference's ṗ_c), the stress-test marks of a state (apex,
/// p' → 0, critical state), the failure line on the triaxial-compression meridian (reports and
/// plots), and the chosen integrator.
template <class M>
concept PlasticModel =
    ConstitutiveModel<M> && requires(const M& model, const State& state, const Mat3& sigma, double pc) {
      { model.yield(sigma, pc) } -> std::convertible_to<double>;
      { model.normalized_yield(sigma, pc) } -> std::convertible_to<double>;
      { model.yield_gradient(sigma, pc) } -> std::convertible_to<Mat3>;
      { model.flow_direction(sigma, pc) } -> std::convertible_to<Mat3>;
      { model.hardening_modulus(sigma, pc) } -> std::convertible_to<double>;
      { model.hardening_rate(sigma, pc, pc, sigma) } -> std::convertible_to<double>;
      { model.marks(state) } -> std::same_as<StateMarks>;
      { model.triaxial_failure_line() } -> std::same_as<FailureLine>;
      { model.integrator() } -> std::same_as<Integrator>;
    };

}  // namespace soilsph
