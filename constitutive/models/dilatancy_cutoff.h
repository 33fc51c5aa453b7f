#pragma once
/// @file
/// The dilatancy cut-off of a perfectly plastic frictional model (D-P, MC): the flow dilates with ψ
/// until the accumulated plastic volumetric strain State::plastic_dilation reaches `dilatancy_cutoff`,
/// then flows with ψ = 0, as PLAXIS's "dilatancy cut-off" stops dilation at a maximum void ratio:
/// from void ratios, cutoff = ln((1 + e_max)/(1 + e0)). The limit is on the plastic volume (PLAXIS's
/// is on the total one; the elastic part, −p/K, is below 1e-3 in the soils here) so that the switch
/// is a property of the plastic state alone, continuous in the increment (integrators/dilatancy_split.h).
/// Why: a constant ψ dilates without bound. A collapse shears its soil to plastic strains of order 1,
/// and with ψ = 5°, 10°, 15° the paper's D-P column grew by 31, 50 and 65 % in volume, its toe at a quarter
/// to a half of the initial density still jostling at 0.1–0.3 m/s after the rest of the deposit had stopped
/// (docs/validation/collapse.md); a real sand stops dilating at its critical state.
///
/// The model past its cut-off is a twin built with ψ = 0, so that every integrator and the CVODE
/// reference use its constants as they are, with no branch inside a return.
#include <cmath>
#include <limits>
#include <memory>

namespace soilsph {

template <class Model>
class DilatancyCutoff {
 public:
  /// True when the model dilates (ψ > 0) and stops at a cut-off.
  bool limits_dilation() const { return non_dilating_ != nullptr; }
  /// The plastic volumetric strain at which dilation stops (+∞: none).
  double dilatancy_cutoff() const { return cutoff_; }
  /// The same model with ψ = 0 (only when limits_dilation()).
  const Model& non_dilating() const { return *non_dilating_; }
  /// The model that flows at the plastic dilation d: this one below the cut-off, its twin from it on.
  const Model& flowing_at(double d) const {
    return limits_dilation() && d >= cutoff_ ? *non_dilating_ : static_cast<const Model&>(*this);
  }

 protected:
  /// Called by the model's constructor with its validated parameters.
  template <class Params>
  void build_cutoff(const Params& params) {
    cutoff_ = params.dilatancy_cutoff;
    if (params.dilatancy_angle > 0.0 && std::isfinite(cutoff_)) {
      Params twin = params;
      twin.dilatancy_angle = 0.0;
      twin.dilatancy_cutoff = std::numeric_limits<double>::infinity();
      non_dilating_ = std::make_shared<const Model>(twin);
    }
  }

 private:
  double cutoff_ = std::numeric_limits<double>::infinity();
  std::shared_ptr<const Model> non_dilating_;  ///< shared by copies of the model
};

/// The model that flows at plastic dilation d, for any model (those without a cut-off: itself).
template <class Model>
const Model& flowing_model(const Model& model, double d) {
  if constexpr (requires { model.flowing_at(d); })
    return model.flowing_at(d);
  else
    return model;
}

/// True for a model whose flow changes at a dilatancy cut-off.
template <class Model>
bool limits_dilation(const Model& model) {
  if constexpr (requires { model.limits_dilation(); })
    return model.limits_dilation();
  else
    return false;
}

/// True for a model that dilates (ψ > 0) with no cut-off.
template <class Model>
bool dilates_without_bound(const Model& model) {
  if constexpr (requires { model.limits_dilation(); })
    return model.params().dilatancy_angle > 0.0 && !model.limits_dilation();
  else
    return false;
}

}  // namespace soilsph
