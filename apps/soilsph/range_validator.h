#pragma once
/// @file
/// CLI11 validators that state the allowed range in plain numbers, as input files do
/// ("--p-initial: 0 is out of range (allowed: 1 <= value <= 1e12 Pa)"), instead of CLI11's own
/// "Value 0 not in range 0.000000 to 1797…(309 digits)". CLI11 prefixes the option's name.
#include <CLI/CLI.hpp>
#include <string_view>
#include <vector>

#include "constitutive/parameters.h"

namespace soilsph::cli {

/// A number in `range`; `unit` follows the range in the message ("Pa", or empty).
CLI::Validator in_range(const Range& range, std::string_view unit = "");
/// A whole number in [lo, hi], also written as e.g. 1e3.
CLI::Validator whole_number_in(long long lo, long long hi);
/// A comma-separated list of numbers, each in `range`. CLI11's own delimiter drops empty items, so
/// that "0.1,,0.2" would pass as two; this refuses them.
CLI::Validator list_in_range(const Range& range, std::string_view unit = "");
/// The numbers of a list that list_in_range accepted.
std::vector<double> split_numbers(const std::string& list);

}  // namespace soilsph::cli
