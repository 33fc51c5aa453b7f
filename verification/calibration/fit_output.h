#pragma once
/// @file
/// A calibration's answer as files in one folder: `fit.json` (everything), `material.toml` (the
/// calibrated material, ready for `soilsph point` and `soilsph collapse`), `curves-NAME.csv` per
/// experiment (measured, fitted and starting values at the readings) and `history.csv` (the misfit
/// after each iteration of each start). docs/reference/calibration.md lists their fields.
#include <span>
#include <string>

#include "verification/calibration/calibrate.h"

namespace soilsph::calibration {

/// Writes the files above into `dir` (created if missing); `provenance` lines (version, command)
/// head each file. std::runtime_error naming the file when one cannot be written.
void write_calibration(const std::string& dir, const CalibrationFile& file, const Calibration& calibration,
                       std::span<const std::string> provenance);

/// The calibrated material as a TOML file's text: a '#' header (what fitted it, with ± standard
/// errors) and the [material] table.
std::string calibrated_material_toml(const CalibrationFile& file, const Calibration& calibration,
                                     std::span<const std::string> provenance);

/// The result in a few lines for the terminal: values ± standard errors, misfits, warnings.
std::string calibration_summary(const CalibrationFile& file, const Calibration& calibration);

}  // namespace soilsph::calibration
