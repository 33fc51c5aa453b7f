#pragma once
/// @file
/// The one path from fitted values to a model: the material's TOML table with the fitted keys
/// rewritten, read again through the validated factory (constitutive/material.h). The calibration
/// never needs to know which model it fits: any model the factory builds, by any numeric key.
///
/// A fitted key names a numeric key of the table (`friction_angle`) or one element of a numeric
/// array, counted from 1 as Fortran counts PROPS(N): `props(3)` is the third value of a UMAT's
/// `props`, `initial_state(1)` the first of its STATEV at the start.
#include <toml++/toml.h>
#include <span>
#include <string>
#include <string_view>

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

/// The number `key` names in `table` (`name` or `name(N)`), or nullptr when there is none.
const toml::node* parameter_node(const toml::table& table, std::string_view key);

/// The keys of `table` a fit may name, for messages: "compression_index, density, props(1) to props(5), ...".
std::string numeric_keys(const toml::table& table);

}  // namespace soilsph::calibration
