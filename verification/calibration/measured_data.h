#pragma once
/// @file
/// A measured laboratory curve read from a CSV file: '#' comment lines, a header row naming the
/// columns (those of a point CSV: eps_a, q, u, ...), then one row of numbers per reading. Only the
/// driven column and the matched columns are read; each must be present, every value of them finite,
/// and the driven column strictly monotonic, or a ParameterError names the file, line and column.
#include <string>
#include <vector>

namespace soilsph::calibration {

/// What the data's numbers are in: stresses and strains are multiplied by these to become SI.
struct DataUnits {
  double stress = 1.0;  ///< Pa per unit of the file's stresses (1e3 for kPa)
  double strain = 1.0;  ///< 1 per unit of the file's strains (0.01 for percent)
};

/// The readings, SI and compression-positive, in the file's order.
struct MeasuredCurve {
  std::string path{};
  std::string against{};                       ///< the driven column's name
  std::vector<double> driven{};                ///< its values, strictly monotonic
  std::vector<std::string> names{};            ///< the matched columns' names
  std::vector<std::vector<double>> columns{};  ///< per matched column, one value per reading
  std::vector<int> lines{};                    ///< the file line of each reading, for messages
};

/// Reads `against` and `match` from the CSV at `path`. `named_by` says where the columns were asked for
/// ("cal.toml: [[experiment]] 2"), for the message when one is missing.
MeasuredCurve read_measured_curve(const std::string& path, const std::string& against,
                                  const std::vector<std::string>& match, const DataUnits& units,
                                  const std::string& named_by);

}  // namespace soilsph::calibration
