#include "verification/paths/strain_path_csv.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "constitutive/parameters.h"

namespace soilsph::verification {

namespace {

constexpr const char* kHeader = "d_xx,d_yy,d_zz,d_xy,d_yz,d_xz";
/// Tensor indices (row, column) of the six columns.
constexpr int kRow[6] = {0, 1, 2, 0, 1, 0};
constexpr int kCol[6] = {0, 1, 2, 1, 2, 2};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string without_spaces(std::string s) {
  std::erase_if(s, [](char c) { return c == ' ' || c == '\t' || c == '\r'; });
  return s;
}

}  // namespace

StrainPath read_strain_path(std::istream& in, const std::string& source) {
  StrainPath path;
  bool header_seen = false;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    const std::string where = source + ":" + std::to_string(number) + ": ";
    if (!header_seen) {
      if (without_spaces(text) != kHeader)
        throw ParameterError(where + "expected the header row \"" + kHeader + "\", got \"" + text + "\"");
      header_seen = true;
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream row(text);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(trim(cell));
    if (text.back() == ',') cells.push_back("");
    if (cells.size() != 6)
      throw ParameterError(where + "expected 6 values (" + kHeader + "), got " +
                           std::to_string(cells.size()));
    Mat3 d = Mat3::Zero();
    for (int c = 0; c < 6; ++c) {
      std::size_t used = 0;
      double value = 0.0;
      try {
        value = std::stod(cells[c], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (cells[c].empty() || used != cells[c].size() || !std::isfinite(value))
        throw ParameterError(where + "column " + std::to_string(c + 1) + ": \"" + cells[c] +
                             "\" is not a finite number");
      d(kRow[c], kCol[c]) = d(kCol[c], kRow[c]) = value;
    }
    path.increments.push_back(d);
    path.sources.push_back(source + ":" + std::to_string(number));
  }
  if (!header_seen) throw ParameterError(source + ": no header row \"" + kHeader + "\"");
  if (path.increments.empty()) throw ParameterError(source + ": no strain increments after the header");
  return path;
}

StrainPath read_strain_path_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ParameterError(path + ": cannot open the strain-path file");
  return read_strain_path(in, path);
}

}  // namespace soilsph::verification
