#pragma once
/// @file
/// What a wall guard did in one step (stages/boundaries.h for the plane's segments,
/// stages/plane_guard.h for space's planes).
#include <cstddef>

namespace soilsph::sph {

struct GuardPushes {
  std::size_t count = 0;  ///< soil particles put back on a wall
  /// Of those, the ones beyond the wall's end or outline (within the guard's reach there): soil that
  /// ran off a floor too short for it, which the blow-up message says.
  std::size_t past_edge = 0;
};

}  // namespace soilsph::sph
