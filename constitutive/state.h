#pragma once
/// @file
/// The state carried by one material point between updates. One struct for every model: models
/// without a hardening variable keep `pc = 0`.
#include <array>

#include "constitutive/tensor.h"

namespace soilsph {

/// The most state variables (NSTATV) a UMAT plug-in may declare (models/umat.h): a fixed capacity so
/// that a state is copied without a heap allocation, set when soilsph is configured
/// (-DSOILSPH_MAX_STATE_VARIABLES=N).
#ifndef SOILSPH_MAX_STATE_VARIABLES
#define SOILSPH_MAX_STATE_VARIABLES 16
#endif
inline constexpr int kMaxStateVariables = SOILSPH_MAX_STATE_VARIABLES;

/// What a UMAT plug-in carries between calls besides the stress (models/umat.h); unused (zero) for
/// every built-in model.
struct UmatVariables {
  std::array<double, kMaxStateVariables> statev{};  ///< STATEV(1..NSTATV)
  std::array<double, 6> strain{};  ///< STRAN: total strain, Voigt 11, 22, 33, 12, 13, 23, engineering shears
  double time = 0.0;               ///< TIME at the start of the next increment (s; increments at a point)
  int increment = 0;               ///< KINC of the last call
};

struct State {
  Mat3 stress = Mat3::Zero();  ///< effective stress σ, tension-positive (Pa)
  double pc = 0.0;             ///< preconsolidation pressure p_c (the paper's p0), compression-positive (Pa)
  double plastic_shear_strain = 0.0;  ///< accumulated equivalent plastic strain ∫ sqrt(2/3 dε^p:dε^p)
  double plastic_multiplier = 0.0;    ///< Δλ of the last update (≥ 0), a diagnostic
  /// Accumulated plastic volumetric strain ∫ tr dε^p, expansion-positive: kept by a model with a
  /// dilatancy cut-off (models/dilatancy_cutoff.h), which stops dilating when it reaches the cut-off;
  /// 0 for every other model.
  double plastic_dilation = 0.0;
  /// Accumulated volumetric strain ∫ tr dε since the initial state, expansion-positive: kept by
  /// Modified Cam-Clay with hardening_volume = "current" (its specific volume v = v0 (1 + this));
  /// 0 for every other model.
  double volumetric_strain = 0.0;
  UmatVariables umat;  ///< a UMAT plug-in's state variables, strain and time
};

/// Where an updated state lies among the corners of a model's stress space that integrators find
/// hard, as the stress test counts them (constitutive/stress_test.h); a model's `marks(state)` says.
struct StateMarks {
  bool at_apex = false;              ///< a plastic state at the apex of a cone or pyramid (s = 0)
  bool near_zero_pressure = false;   ///< a hardening model's p' < 0.01 p_c
  bool near_critical_state = false;  ///< a plastic state within 5 % of the critical-state stress ratio
};

/// Adds a plastic strain increment to the accumulated measure of `state`. The accumulated tensor is
/// not kept: no output, hardening law or driver reads it (MCC hardens on each increment's volumetric
/// part), and carrying it cost the SPH step a second rotation and 72 bytes per soil particle.
inline void accumulate_plastic_strain(State& state, const Mat3& d_plastic_strain) {
  state.plastic_shear_strain += std::sqrt(2.0 / 3.0 * ddot(d_plastic_strain, d_plastic_strain));
}
/// The same from dε^p:dε^p, for a return that knows it in closed form without the tensor.
inline void accumulate_plastic_strain_from_squared_norm(State& state, double squared_norm) {
  state.plastic_shear_strain += std::sqrt(2.0 / 3.0 * squared_norm);
}

}  // namespace soilsph
