#pragma once
/// @file
/// The initial state of one soil particle under a geostatic stress, the same in 2D and 3D: the
/// stress, the model's initial hardening (MCC's p_c) and the check that it lies inside the yield
/// surface; and the smallest K0 for which the base of a soil column does (initial_state.h,
/// initial_state_3d.h).
#include <functional>
#include <optional>
#include <string>

#include "constitutive/admissible_state.h"
#include "constitutive/material.h"
#include "sph/scene_settings.h"

namespace soilsph::sph {

/// The model's initial hardening state (its hook: MCC's p_c, 0 for models without one).
template <class Model>
double initial_preconsolidation(const Model& model, const Mat3& sigma, const InitialConditions& c) {
  return model.initial_preconsolidation(sigma, c.overconsolidation_ratio, c.preconsolidation_floor);
}

/// A soil particle at rest under `sigma`: for MCC p_c = max(OCR · p_c,yield, p_c,floor) (the model's
/// hook), or none if (σ, p_c) lies outside the yield surface.
template <class Model>
std::optional<State> geostatic_state(const Model& model, const Mat3& sigma, const InitialConditions& c) {
  State s{};
  s.stress = sigma;
  s.pc = initial_preconsolidation(model, s.stress, c);
  if (!admissible_state(model, s)) return std::nullopt;
  return s;
}

/// "SOURCE: the geostatic stress at POSITION m lies outside the yield surface of TABLE; K0 = k0
/// ([initial] lateral_stress_ratio) is not admissible for it".
std::string inadmissible_geostatic_message(const std::string& source, const std::string& position,
                                           const std::string& table, double k0);

/// The smallest K0 in (0, 1] for which `base_stress(density, K0)`, the geostatic stress at the
/// soil's base, lies inside the material's yield surface (bisection on the model's own yield
/// function to 10⁻¹²); 0 if every K0 > 0 is admissible.
double smallest_admissible_lateral_stress_ratio(
    const Material& material, const std::function<Mat3(double density, double k0)>& base_stress);

}  // namespace soilsph::sph
