#include "verification/calibration/fit_output.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "constitutive/material_description.h"
#include "constitutive/parameters.h"

namespace soilsph::calibration {

namespace {
namespace fs = std::filesystem;

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (c == '\n')
      out += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20)
      out += "\\u00" + std::string(1, "0123456789abcdef"[c >> 4]) + "0123456789abcdef"[c & 15];
    else
      out += c;
  }
  return out + "\"";
}

/// A JSON number that reads back exactly; null for ±∞ and NaN, which JSON cannot hold.
std::string json_number(double x) {
  return std::isfinite(x) ? exact_number(x) : "null";
}

template <class Item, class Write>
std::string json_array(const std::vector<Item>& items, Write write) {
  std::string out = "[";
  for (std::size_t k = 0; k < items.size(); ++k) out += (k ? ", " : "") + write(items[k]);
  return out + "]";
}

std::string json_numbers(const std::vector<double>& values) {
  return json_array(values, json_number);
}

/// The value of one TOML node as a TOML file writes it (numbers exactly).
std::string toml_value(const toml::node& node) {
  if (const auto x = node.value_exact<double>()) return exact_number(*x);
  if (const auto s = node.value_exact<std::string>()) return json_string(*s);  // a TOML basic string
  std::ostringstream out;
  out << toml::toml_formatter(node);
  return out.str();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out << text;
  out.flush();
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

std::string fit_json(const CalibrationFile& file, const Calibration& c,
                     std::span<const std::string> provenance) {
  const FitStatistics& s = c.statistics;
  const LeastSquaresResult& best = c.starts[c.best].fit;
  std::ostringstream j;
  j << "{\n  \"provenance\": "
    << json_array(std::vector<std::string>(provenance.begin(), provenance.end()), json_string)
    << ",\n  \"calibration_file\": " << json_string(file.path)
    << ",\n  \"model\": " << json_string(file.material.table["model"].value_or(std::string()))
    << ",\n  \"method\": "
    << json_string(file.options.method == TrustRegion::Dogleg ? "dogleg" : "levenberg-marquardt")
    << ",\n  \"converged\": " << (best.converged ? "true" : "false")
    << ",\n  \"stop\": " << json_string(best.stop)
    << ",\n  \"iterations\": " << (best.history.empty() ? 0 : best.history.back().iteration)
    << ",\n  \"model_evaluations\": " << c.evaluations << ",\n  \"seconds\": " << json_number(c.seconds)
    << ",\n  \"cost\": " << json_number(s.cost) << ",\n  \"residuals\": " << s.residuals
    << ",\n  \"degrees_of_freedom\": " << s.degrees_of_freedom
    << ",\n  \"residual_variance\": " << json_number(s.residual_variance)
    << ",\n  \"t_95\": " << json_number(s.t_95) << ",\n  \"parameters\": [";
  for (std::size_t k = 0; k < s.parameters.size(); ++k) {
    const ParameterEstimate& e = s.parameters[k];
    j << (k ? "," : "") << "\n    {\"key\": " << json_string(e.key) << ", \"value\": " << json_number(e.value)
      << ", \"standard_error\": " << json_number(e.standard_error) << ", \"interval_95\": ["
      << json_number(e.lower_95) << ", " << json_number(e.upper_95) << "], \"bounds\": ["
      << json_number(e.lower_bound) << ", " << json_number(e.upper_bound)
      << "], \"start\": " << json_number(e.start) << ", \"on_bound\": " << (e.on_bound ? "true" : "false")
      << "}";
  }
  j << "\n  ],\n  \"correlation\": [";
  for (Eigen::Index i = 0; i < s.correlation.rows(); ++i) {
    std::vector<double> row(s.correlation.row(i).begin(), s.correlation.row(i).end());
    j << (i ? "," : "") << "\n    " << json_numbers(row);
  }
  j << "\n  ],\n  \"misfit\": [";
  for (std::size_t k = 0; k < c.misfits.size(); ++k) {
    const ColumnMisfit& m = c.misfits[k];
    const Experiment& e = file.experiments[m.experiment];
    j << (k ? "," : "") << "\n    {\"experiment\": " << json_string(e.name)
      << ", \"column\": " << json_string(m.column) << ", \"rms\": " << json_number(m.rms)
      << ", \"range\": " << json_number(m.range) << ", \"rms_normalised\": " << json_number(m.rms_normalised)
      << "}";
  }
  j << "\n  ],\n  \"experiments\": [";
  for (std::size_t k = 0; k < file.experiments.size(); ++k) {
    const Experiment& e = file.experiments[k];
    j << (k ? "," : "") << "\n    {\"name\": " << json_string(e.name)
      << ", \"programme\": " << json_string(e.programme_path) << ", \"data\": " << json_string(e.data.path)
      << ", \"against\": " << json_string(e.data.against)
      << ", \"match\": " << json_array(e.data.names, json_string) << ", \"weight\": " << json_number(e.weight)
      << ", \"readings\": " << e.data.driven.size()
      << ", \"curves\": " << json_string("curves-" + e.name + ".csv") << "}";
  }
  j << "\n  ],\n  \"starts\": [";
  for (std::size_t k = 0; k < c.starts.size(); ++k) {
    const StartRun& run = c.starts[k];
    j << (k ? "," : "") << "\n    {\"start\": " << json_numbers(run.start)
      << ", \"cost\": " << json_number(run.fit.residuals.squaredNorm())
      << ", \"converged\": " << (run.fit.converged ? "true" : "false")
      << ", \"model_evaluations\": " << run.fit.evaluations << "}";
  }
  j << "\n  ],\n  \"best_start\": " << c.best << ",\n  \"warnings\": " << json_array(s.warnings, json_string)
    << ",\n  \"material\": \"material.toml\"\n}\n";
  return j.str();
}

std::string curves_csv(const Experiment& e, const ModelCurve& fitted, const ModelCurve& initial,
                       std::span<const std::string> provenance) {
  std::ostringstream out;
  out << "# soilsph calibrate: " << e.where << "; compression-positive; SI (strains 1; stresses Pa); "
      << "NAME_measured from " << e.data.path
      << "; NAME_fitted and NAME_start: the model at the readings with "
      << "the fitted and the starting parameters\n";
  for (const std::string& line : provenance) out << "# " << line << '\n';
  out << "line," << e.data.against;
  for (const std::string& name : e.data.names)
    out << ',' << name << "_measured," << name << "_fitted," << name << "_start";
  out << '\n' << std::setprecision(17);
  for (std::size_t k = 0; k < e.data.driven.size(); ++k) {
    out << e.data.lines[k] << ',' << e.data.driven[k];
    for (std::size_t c = 0; c < e.data.names.size(); ++c)
      out << ',' << e.data.columns[c][k] << ',' << fitted.columns[c][k] << ',' << initial.columns[c][k];
    out << '\n';
  }
  return out.str();
}

std::string history_csv(const CalibrationFile& file, const Calibration& c,
                        std::span<const std::string> provenance) {
  std::ostringstream out;
  out << "# soilsph calibrate: the misfit (cost = sum of squared normalised residuals) after each iteration "
         "of "
         "each start, and the parameters there (physical units of the material's keys)\n";
  for (const std::string& line : provenance) out << "# " << line << '\n';
  out << "start,iteration,cost";
  for (const FitParameter& p : file.parameters) out << ',' << p.key;
  out << '\n' << std::setprecision(17);
  std::vector<ParameterScaling> scalings;
  for (const FitParameter& p : file.parameters) scalings.emplace_back(p);
  for (std::size_t s = 0; s < c.starts.size(); ++s) {
    for (const Iterate& it : c.starts[s].fit.history) {
      out << s << ',' << it.iteration << ',' << it.cost;
      for (std::size_t k = 0; k < scalings.size(); ++k)
        out << ',' << scalings[k].to_physical(it.z(static_cast<Eigen::Index>(k)));
      out << '\n';
    }
  }
  return out.str();
}

/// `value ± error` with the error's two significant digits deciding the value's.
std::string with_error(double value, double error) {
  std::ostringstream out;
  out << std::setprecision(8) << value << " ± " << std::setprecision(2) << error;
  return out.str();
}

}  // namespace

std::string calibrated_material_toml(const CalibrationFile& file, const Calibration& c,
                                     std::span<const std::string> provenance) {
  std::ostringstream out;
  out << "# Calibrated by soilsph calibrate from " << file.path << " (" << file.material.source << " with ";
  for (std::size_t k = 0; k < c.statistics.parameters.size(); ++k) {
    const ParameterEstimate& e = c.statistics.parameters[k];
    out << (k ? ", " : "") << e.key << " = " << with_error(e.value, e.standard_error);
  }
  out << "; ± one standard error, fit.json beside this file has the rest). SI units.\n";
  for (const std::string& line : provenance) out << "# " << line << '\n';
  out << "[material]\n";
  // The factory's keys in their usual order, then any others the model reads.
  std::vector<std::string> keys;
  for (const std::string_view key : material_keys())
    if (c.material.contains(key)) keys.emplace_back(key);
  for (const auto& [key, value] : c.material)
    if (std::find(keys.begin(), keys.end(), key.str()) == keys.end()) keys.emplace_back(key.str());
  for (const std::string& key : keys) out << key << " = " << toml_value(*c.material.get(key)) << '\n';
  return out.str();
}

void write_calibration(const std::string& dir, const CalibrationFile& file, const Calibration& c,
                       std::span<const std::string> provenance) {
  const fs::path folder(dir);
  std::error_code error;
  fs::create_directories(folder, error);
  if (error) throw std::runtime_error(dir + ": cannot create the folder (" + error.message() + ")");
  write_file(folder / "fit.json", fit_json(file, c, provenance));
  write_file(folder / "material.toml", calibrated_material_toml(file, c, provenance));
  write_file(folder / "history.csv", history_csv(file, c, provenance));
  for (std::size_t e = 0; e < file.experiments.size(); ++e)
    write_file(folder / ("curves-" + file.experiments[e].name + ".csv"),
               curves_csv(file.experiments[e], c.fitted[e], c.initial[e], provenance));
}

std::string calibration_summary(const CalibrationFile& file, const Calibration& c) {
  const LeastSquaresResult& best = c.starts[c.best].fit;
  std::ostringstream out;
  out << best.stop << " after " << (best.history.empty() ? 0 : best.history.back().iteration)
      << " iterations (" << c.starts.size() << " start(s), " << c.evaluations << " model evaluations, "
      << std::setprecision(3) << c.seconds << " s)\n";
  for (const ParameterEstimate& e : c.statistics.parameters)
    out << "  " << e.key << " = " << with_error(e.value, e.standard_error)
        << "  (95 %: " << std::setprecision(6) << e.lower_95 << " to " << e.upper_95 << "; start " << e.start
        << ")\n";
  for (const ColumnMisfit& m : c.misfits)
    out << "  misfit " << file.experiments[m.experiment].name << " " << m.column << ": rms "
        << std::setprecision(4) << m.rms << " (" << 100.0 * m.rms_normalised << " % of its range)\n";
  for (const std::string& w : c.statistics.warnings) out << "warning: " << w << '\n';
  return out.str();
}

}  // namespace soilsph::calibration
