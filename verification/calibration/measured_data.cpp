#include "verification/calibration/measured_data.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "constitutive/parameters.h"
#include "verification/calibration/point_columns.h"

namespace soilsph::calibration {

namespace {

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(trimmed(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();  // a trailing empty field
  return fields;
}

/// The finite number in `text`, or a ParameterError naming the file, line and column.
double number_in(const std::string& text, const std::string& where, const std::string& column) {
  if (text.empty()) throw ParameterError(where + ": " + column + " is missing (an empty field)");
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size())
    throw ParameterError(where + ": " + column + " = " + text + " is not a number");
  if (!std::isfinite(x))
    throw ParameterError(where + ": " + column + " = " + text + " is not a finite number");
  return x;
}

double scale_of(const std::string& name, const DataUnits& units) {
  return point_column(name)->quantity == Quantity::Stress ? units.stress : units.strain;
}

}  // namespace

MeasuredCurve read_measured_curve(const std::string& path, const std::string& against,
                                  const std::vector<std::string>& match, const DataUnits& units,
                                  const std::string& named_by) {
  std::ifstream in(path);
  if (!in) throw ParameterError(path + ": cannot open the data file (" + named_by + ")");
  MeasuredCurve curve{.path = path, .against = against, .names = match};
  curve.columns.resize(match.size());
  std::vector<std::string> header;
  std::vector<std::size_t> index;  // of `against`, then of each matched column
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = trimmed(line);
    if (text.empty() || text.front() == '#') continue;
    const std::string where = path + ":" + std::to_string(number);
    const std::vector<std::string> fields = fields_of(text);
    if (header.empty()) {
      header = fields;
      std::string names;
      for (const std::string& name : header) names.append(names.empty() ? "" : ", ").append(name);
      std::vector<std::string> wanted_columns{against};
      wanted_columns.insert(wanted_columns.end(), match.begin(), match.end());
      for (const std::string& wanted : wanted_columns) {
        const auto it = std::find(header.begin(), header.end(), wanted);
        if (it == header.end())
          throw ParameterError(path + ": no column " + wanted + " (its header row at line " +
                               std::to_string(number) + " names " + names + "), which " + named_by +
                               " compares");
        index.push_back(static_cast<std::size_t>(it - header.begin()));
      }
      continue;
    }
    if (fields.size() != header.size())
      throw ParameterError(where + ": " + std::to_string(fields.size()) +
                           " fields where the header row has " + std::to_string(header.size()));
    const double x = number_in(fields[index[0]], where, against) * scale_of(against, units);
    if (!curve.driven.empty()) {
      const double previous = curve.driven.back();
      const bool direction_known = curve.driven.size() >= 2;
      const bool increasing = direction_known && curve.driven[1] > curve.driven[0];
      if (x == previous || (direction_known && (x > previous) != increasing))
        throw ParameterError(where + ": " + against + " = " + fields[index[0]] + " after " +
                             format_number(previous / scale_of(against, units)) + " at line " +
                             std::to_string(curve.lines.back()) + ": the driven column must be strictly " +
                             (!direction_known ? "monotonic"
                              : increasing     ? "increasing"
                                               : "decreasing"));
    }
    curve.driven.push_back(x);
    for (std::size_t c = 0; c < match.size(); ++c)
      curve.columns[c].push_back(number_in(fields[index[c + 1]], where, match[c]) *
                                 scale_of(match[c], units));
    curve.lines.push_back(number);
  }
  if (header.empty()) throw ParameterError(path + ": no header row (the data file is empty)");
  if (curve.driven.size() < 2)
    throw ParameterError(path + ": " + std::to_string(curve.driven.size()) +
                         " reading(s); a curve needs at least 2");
  return curve;
}

}  // namespace soilsph::calibration
