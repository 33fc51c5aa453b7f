#pragma once
/// @file
/// Pressures on the command line with their unit: `100kPa`, `0.1MPa`, `100000Pa`, or a plain number
/// in Pa. Read into Pa (SI, as every file soilsph writes), correctly rounded: the decimal exponent of
/// the unit is added to the number's own before it is converted, so `0.1MPa` is exactly 1e5.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "constitutive/parameters.h"

namespace soilsph::cli {

/// The units a pressure option accepts, as written after the number.
inline constexpr std::string_view kPressureUnits = "Pa, kPa, MPa, GPa";

/// `text` as a pressure in Pa, or nothing if it is not a number followed by nothing or one of
/// kPressureUnits (case as written there: "kpa" and "Mpa" are refused, "mPa" would be millipascal).
std::optional<double> parse_pressure(std::string_view text);

/// A CLI11 validator for a pressure option: accepts a pressure in `range` (Pa) and hands CLI11 its
/// value in Pa; a bad unit or number is refused naming the allowed units (CLI11 names the option).
CLI::Validator pressure_in(const Range& range);

}  // namespace soilsph::cli
