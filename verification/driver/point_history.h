#pragma once
/// @file
/// What a material-point run produces: the total strain and the model state after each increment,
/// the initial state first. Shared by the mixed-control driver and the CVODE reference.
#include <vector>

#include "constitutive/state.h"

namespace soilsph::verification {

/// Total strain (tension-positive) and state at one increment.
struct PointSample {
  Mat3 strain = Mat3::Zero();
  State state;
};
using PointHistory = std::vector<PointSample>;

}  // namespace soilsph::verification
