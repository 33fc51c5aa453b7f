#pragma once
/// @file
/// The statistics the bench commands quote: a machine shared with other jobs makes single timings
/// noisy, so each figure is the median of alternated repeats.
#include <algorithm>
#include <vector>

namespace soilsph::cli {

/// The median of v (the mean of the middle two for an even count); v must not be empty.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace soilsph::cli
