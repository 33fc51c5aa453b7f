#pragma once
/// @file
/// The one path from fitted values to a model: the material's TOML table with the fitted keys
/// rewritten, read again through the validated factory (constitutive/material.h). The calibration
/// never needs to know which model it fits: any model the factory builds, by any numeric key.
#include <toml++/toml.h>
#include <span>
#include <string>

#include "constitutive/material.h"

namespace soilsph::calibration {

/// A material as a TOML table, with the parameters to vary named by their keys.
struct MaterialTemplate {
  toml::table table;              ///< the [material] table as the factory resolved it (every key it reads)
  std::string source;             ///< names the table in messages
  std::vector<std::string> keys;  ///< the keys the values replace, in order

  /// The table with keys[k] = values[k].
  toml::table with(std::span<const double> values) const;
  /// That table read through read_material(); a ParameterError names `source` and the key when a
  /// value (or a combination, e.g. κ ≥ λ) is refused.
  Material build(std::span<const double> values) const;
};

/// The numeric keys of `table`, for messages: "compression_index, density, ...".
std::string numeric_keys(const toml::table& table);

}  // namespace soilsph::calibration
