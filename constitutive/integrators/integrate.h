#pragma once
/// @file
/// One material-point update: the objective rotation by the spin increment (Jaumann terms of
/// eq 21/28), then the stress integration by the model's chosen scheme; for a model with a dilatancy
/// cut-off, split where the increment reaches it (dilatancy_split.h). Instantiated inside each
/// model's translation unit; the switch is decided once per model, so it is a predictable branch.
#include <stdexcept>

#include "constitutive/integrators/dilatancy_split.h"
#include "constitutive/integrators/explicit_rate.h"
#include "constitutive/integrators/implicit_cam_clay.h"
#include "constitutive/integrators/implicit_drucker_prager.h"
#include "constitutive/integrators/implicit_mohr_coulomb.h"
#include "constitutive/integrators/integrator.h"
#include "constitutive/integrators/substep.h"
#include "constitutive/models/dilatancy_cutoff.h"
#include "constitutive/rotation.h"

namespace soilsph {

template <class Model>
State integrate_by_scheme(const Model& model, const State& state, const Mat3& strain_increment,
                          const Mat3& spin_increment) {
  const State rotated = rotate_state(state, spin_increment);
  switch (model.integrator()) {
    case Integrator::Explicit: return explicit_update(model, rotated, strain_increment);
    case Integrator::Substep: return substep_update(model, rotated, strain_increment);
    case Integrator::Implicit: return implicit_update(model, rotated, strain_increment);
  }
  throw std::logic_error("integrate: unhandled integrator");
}

template <class Model>
State integrate(const Model& model, const State& state, const Mat3& strain_increment,
                const Mat3& spin_increment) {
  if constexpr (requires { model.non_dilating(); }) {
    if (model.limits_dilation())
      return integrate_across_dilatancy_cutoff(model, state, strain_increment, spin_increment,
                                               integrate_by_scheme<Model>);
  }
  return integrate_by_scheme(model, state, strain_increment, spin_increment);
}

}  // namespace soilsph
