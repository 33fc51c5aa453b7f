#pragma once
/// @file
/// A calibration file (`soilsph calibrate FILE.toml`, docs/reference/calibration.md): the material
/// with its fixed parameters, the parameters to fit with their bounds, and the experiments (a
/// programme that reproduces each test's loading, the measured CSV, the driven column and the
/// columns compared). Everything is validated when read: a bad value is a ParameterError that
/// names the file and the key, or the data file, its line and column.
///
///   material = "clay.toml"            # a material file (relative to this file), or a [material] table
///   [fit]
///   parameters = { compression_index = [0.05, 0.5], friction_angle = [15, 45] }
///   method = "levenberg-marquardt"    # or "dogleg"
///   [[experiment]]
///   programme = "cu-ocr1.toml"        # its material is replaced by the one being fitted
///   data = "cu-ocr1.csv"
///   against = "eps_a"
///   match = ["q", "u"]
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "verification/calibration/material_values.h"
#include "verification/calibration/measured_data.h"
#include "verification/programme/programme_file.h"

namespace soilsph::calibration {

/// One parameter to fit: a numeric key of the material, its bounds, and its start (the material's
/// value), lower < start < upper.
struct FitParameter {
  std::string key;
  double lower = 0.0;
  double upper = 0.0;
  double start = 0.0;
};

/// One laboratory test.
struct Experiment {
  std::string name;            ///< labels its outputs (default: the data file's name without .csv)
  std::string where;           ///< "FILE: [[experiment]] k (NAME)", for messages
  std::string programme_path;  ///< the programme file, as found from the calibration file
  toml::table programme;       ///< that file parsed; its material is replaced by the fitted one
  MeasuredCurve data;          ///< SI, compression-positive
  double weight = 1.0;         ///< multiplies the experiment's squared residuals
};

enum class TrustRegion { LevenbergMarquardt, Dogleg };

struct FitOptions {
  TrustRegion method = TrustRegion::LevenbergMarquardt;
  int max_iterations = 100;
  /// Relative step of the scaled parameters below which the fit has converged (GSL's xtol).
  double tolerance = 1e-10;
  /// Forward-difference step of the scaled parameters for the Jacobian.
  double difference_step = 1e-7;
  int starts = 1;     ///< 1: the material's values only; more: also random starts inside the bounds
  unsigned seed = 1;  ///< of the random starts
};

struct CalibrationFile {
  std::string path;
  MaterialTemplate material;  ///< keys: the fitted parameters', in the order of `parameters`
  std::vector<FitParameter> parameters{};
  std::vector<Experiment> experiments{};
  FitOptions options{};
};

CalibrationFile read_calibration_file(const std::string& path);

/// Experiment `e`'s programme with `material` (a [material] table) in place of its own.
verification::ProgrammeFile experiment_programme(const Experiment& e, const toml::table& material);

}  // namespace soilsph::calibration
