#pragma once
/// @file
/// What a material-point run produces: the total strain and the model state after each increment,
/// the initial state first. Shared by the mixed-control driver and the CVODE reference.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "constitutive/state.h"

namespace soilsph::verification {

/// Total strain (tension-positive) and state at one increment.
struct PointSample {
  Mat3 strain = Mat3::Zero();
  State state;
  double pore_pressure = 0.0;  ///< excess pore pressure u (Pa, compression-positive); 0 when drained
};
using PointHistory = std::vector<PointSample>;

/// A run that could not complete one increment: which one (`leg` and `increment` count from 0) and
/// why, so that callers can name it in their own terms (a strain-path file's row, a strain target).
/// what() is the reason followed by " in increment k of leg l" (counting from 1). `completed` holds
/// the samples up to the last completed increment when the driver could give them (a leg that
/// reached the soil's strength), so that the curve can be written up to there; empty otherwise.
class IncrementError : public std::runtime_error {
 public:
  IncrementError(const std::string& reason, std::size_t leg, int increment, PointHistory completed = {})
      : std::runtime_error(reason + " in increment " + std::to_string(increment + 1) + " of leg " +
                           std::to_string(leg + 1)),
        reason(reason),
        leg(leg),
        increment(increment),
        completed(std::move(completed)) {}
  std::string reason;
  std::size_t leg;
  int increment;
  PointHistory completed;
};

}  // namespace soilsph::verification
