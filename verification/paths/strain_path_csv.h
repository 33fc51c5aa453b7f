#pragma once
/// @file
/// Reading a strain path: a CSV of strain-increment tensors, one increment per row, columns
/// d_xx,d_yy,d_zz,d_xy,d_yz,d_xz (tension-positive tensor components, so d_xy = Δε_xy, half the
/// engineering shear). The first non-comment row must be exactly that header; lines starting with
/// '#' and blank lines are skipped.
#include <istream>
#include <string>
#include <vector>

#include "constitutive/tensor.h"

namespace soilsph::verification {

/// A strain path as read: its increments and where each was read, "SOURCE:LINE", for messages.
struct StrainPath {
  std::vector<Mat3> increments;
  std::vector<std::string> sources;
};

/// The increments of the CSV `in`; `source` names it in errors. Throws ParameterError naming
/// source and line for a missing/wrong header, a row without exactly 6 numbers, a non-finite
/// value, or a file without increments. (Their range is checked with the test: build_legs().)
StrainPath read_strain_path(std::istream& in, const std::string& source);
/// The increments of the CSV file `path` (ParameterError if it cannot be opened).
StrainPath read_strain_path_file(const std::string& path);

}  // namespace soilsph::verification
