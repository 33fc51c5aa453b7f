#pragma once
/// @file
/// The yield surfaces of a model as the CVODE reference's rate equations see them. A smooth model
/// (D-P, MCC) has one, its yield function. A model that exposes its planes (Mohr–Coulomb's pyramid
/// and tension cut-off, `planes()`) has several, and where the stress lies on more than one (an
/// edge, a corner, the apex) each flows with its own multiplier (Koiter 1953):
///   ε̇^p = Σ_{k∈J} λ̇_k n_g,k,   Σ_{k∈J} (n_f,j : D : n_g,k + H_j δ_jk) λ̇_k = n_f,j : D : ε̇   (j ∈ J),
/// where the active set J is the one whose multipliers are all ≥ 0 while every other surface the
/// stress lies on has ḟ ≤ 0: the Kuhn–Tucker conditions in rate form (docs/method/verification.md).
#include <array>

#include "constitutive/material.h"

namespace soilsph::verification {

inline constexpr int kMaxSurfaces = 6;

/// One surface at a state: its normalized value (≥ 0 on or outside it), ∂f/∂σ, ∂g/∂σ and the
/// hardening term H of its consistency condition.
struct Surface {
  double value = 0.0;
  Mat3 gradient = Mat3::Zero();
  Mat3 flow = Mat3::Zero();
  double hardening = 0.0;
};
using Surfaces = std::array<Surface, kMaxSurfaces>;

template <class Model>
concept HasPlanes = requires(const Model& model, const Mat3& sigma) {
  model.planes(sigma);
  { model.plane_count() } -> std::convertible_to<int>;
};

/// How many surfaces the model has (0 for an elastic one).
template <class Model>
int surface_count(const Model& model) {
  if constexpr (HasPlanes<Model>)
    return model.plane_count();
  else
    return PlasticModel<Model> ? 1 : 0;
}

/// Every surface of the model at (σ, p_c); the first surface_count() entries are valid.
template <class Model>
Surfaces surfaces(const Model& model, const Mat3& sigma, double pc) {
  Surfaces s;
  if constexpr (HasPlanes<Model>) {
    static_assert(!Model::kHasPreconsolidation, "planes of a hardening model need their H");
    const auto planes = model.planes(sigma);
    for (int k = 0; k < model.plane_count(); ++k)
      s[k] = {planes[k].value, planes[k].gradient, planes[k].flow, 0.0};
  } else if constexpr (PlasticModel<Model>) {
    s[0] = {model.normalized_yield(sigma, pc), model.yield_gradient(sigma, pc),
            model.flow_direction(sigma, pc), model.hardening_modulus(sigma, pc)};
  }
  return s;
}

/// The normalized values alone: what the switching functions of the surfaces that do not flow need.
template <class Model>
std::array<double, kMaxSurfaces> surface_values(const Model& model, const Mat3& sigma, double pc) {
  std::array<double, kMaxSurfaces> v{};
  if constexpr (HasPlanes<Model>) {
    const auto planes = model.planes(sigma);
    for (int k = 0; k < model.plane_count(); ++k) v[k] = planes[k].value;
  } else if constexpr (PlasticModel<Model>) {
    v[0] = model.normalized_yield(sigma, pc);
  }
  return v;
}

}  // namespace soilsph::verification
