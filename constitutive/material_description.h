#pragma once
/// @file
/// A material as data for provenance: every parameter of the chosen model, defaults resolved, so a
/// result can say exactly which material produced it (point CSV headers).
#include <string>
#include <utility>
#include <vector>

#include "constitutive/material.h"

namespace soilsph {

/// (key, value) for `model` and every key the model uses, in the order of the model's Params::fields
/// list; values as TOML reads them (strings quoted, numbers as exact_number()).
std::vector<std::pair<std::string, std::string>> material_parameters(const Material& material);

/// material_parameters() as one line: `key = value; key = value; ...`.
std::string describe_material(const Material& material);

}  // namespace soilsph
