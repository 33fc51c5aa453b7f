#include "verification/calibration/calibration_file.h"

#include <algorithm>
#include <filesystem>

#include "constitutive/parameters.h"
#include "verification/calibration/point_columns.h"
#include "verification/driver/rate_independence.h"
#include "verification/programme/programme_file.h"

namespace soilsph::calibration {

namespace {
namespace fs = std::filesystem;

/// `name` as found from the calibration file at `path` (relative names are relative to its folder).
std::string beside(const std::string& path, const std::string& name) {
  return (fs::path(path).parent_path() / name).lexically_normal().string();
}

/// The [material] table (inline, or of the file `material` names) as the factory resolves it.
MaterialTemplate read_material_template(const toml::table& root, const std::string& path) {
  const toml::node* node = root.get("material");
  if (!node) throw ParameterError(path + ": no material (material = \"FILE\" or a [material] table)");
  toml::table holder;
  std::string source = path;
  if (const auto file = node->value<std::string>()) {
    source = beside(path, *file);
    if (!fs::exists(source))
      throw ParameterError(path + ": material = \"" + *file + "\": no such file (" + source + ")");
    holder = parse_toml_file(source);
  } else if (const toml::table* table = node->as_table()) {
    holder.insert("material", *table);
  } else {
    throw ParameterError(path + ": material must be a file name or a [material] table");
  }
  const toml::table* table = holder["material"].as_table();
  if (!table) throw ParameterError(source + ": no [material] table");
  const TableReader reader(*table, source, "material");
  warn_if_rate_dependent(read_material(reader), source);
  toml::table resolved = reader.resolved();
  // A UMAT's library is found from the file that names it; the calibrated material.toml is written
  // elsewhere, so it names the library by its full path.
  if (const auto library = resolved["library"].value<std::string>();
      library && fs::path(*library).is_relative())
    resolved.insert_or_assign("library", fs::absolute(beside(source, *library)).lexically_normal().string());
  return {.table = std::move(resolved), .source = source, .keys = {}};
}

/// [fit] parameters = { key = [lower, upper], ... } in the file's order, each checked against the
/// material: a numeric key of its model, bounds in order and accepted by the model, the start inside.
std::vector<FitParameter> read_parameters(const toml::table& fit, const std::string& path,
                                          const MaterialTemplate& material) {
  const std::string where = path + ": [fit] parameters";
  const toml::table* table = fit["parameters"].as_table();
  if (!table || table->empty())
    throw ParameterError(where +
                         " must name the parameters to fit with their bounds, e.g. "
                         "parameters = { friction_angle = [15, 45] }");
  std::vector<std::pair<toml::source_position, std::string>> order;
  for (const auto& [key, value] : *table) order.emplace_back(value.source().begin, std::string(key.str()));
  std::sort(order.begin(), order.end());
  const std::string model = material.table["model"].value_or(std::string());
  std::vector<FitParameter> parameters;
  for (const auto& [position, key] : order) {
    const std::string at = where + "." + key;
    const toml::node* start = parameter_node(material.table, key);
    if (!start)
      throw ParameterError(at + ": not a numeric parameter of " + model +
                           " (its numeric keys: " + numeric_keys(material.table) + ")");
    const toml::array* bounds = table->get(key)->as_array();
    const auto bound = [&](std::size_t k) {
      const std::optional<double> x = bounds->get(k)->value<double>();
      if (!x || bounds->get(k)->is_boolean() || !std::isfinite(*x))
        throw ParameterError(at + " must be [lower, upper], two finite numbers");
      return *x;
    };
    if (!bounds || bounds->size() != 2)
      throw ParameterError(at + " must be [lower, upper], two finite numbers");
    FitParameter p{.key = key, .lower = bound(0), .upper = bound(1), .start = *start->value<double>()};
    if (!(p.lower < p.upper))
      throw ParameterError(at + " = [" + format_number(p.lower) + ", " + format_number(p.upper) +
                           "]: the bounds are reversed or equal (lower < upper)");
    if (!(p.lower < p.start && p.start < p.upper))
      throw ParameterError(at + " = [" + format_number(p.lower) + ", " + format_number(p.upper) +
                           "]: the start " + format_number(p.start) + " (the material's " + key + ", " +
                           material.source + ") is not strictly inside the bounds");
    parameters.push_back(p);
  }
  // Each bound must be a value the model accepts with the other parameters somewhere the fit may take
  // them: at their starts, or at any corner of their bounds (κ < λ lets λ's lower bound pass when
  // κ's lower bound is below it).
  MaterialTemplate probe = material;
  for (const FitParameter& p : parameters) probe.keys.push_back(p.key);
  const auto accepted = [&](std::vector<double> values) {
    try {
      probe.build(values);
      return true;
    } catch (const ParameterError&) {
      return false;
    }
  };
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    for (const double bound : {parameters[k].lower, parameters[k].upper}) {
      std::vector<double> at_starts;
      for (const FitParameter& p : parameters) at_starts.push_back(p.start);
      at_starts[k] = bound;
      bool somewhere = accepted(at_starts);
      for (std::size_t corner = 0; !somewhere && corner < (std::size_t{1} << parameters.size()); ++corner) {
        std::vector<double> values = at_starts;
        for (std::size_t j = 0; j < parameters.size(); ++j)
          if (j != k) values[j] = (corner >> j) & 1 ? parameters[j].upper : parameters[j].lower;
        somewhere = accepted(values);
      }
      if (somewhere) continue;
      try {
        probe.build(at_starts);
      } catch (const ParameterError& e) {
        throw ParameterError(
            where + "." + parameters[k].key + ": the bound " + format_number(bound) +
            " is refused by the model with the other parameters at their starts and bounds: " + e.what());
      }
    }
  }
  return parameters;
}

FitOptions read_options(const TableReader& t) {
  FitOptions o;
  o.method = t.choice_or("method", "levenberg-marquardt", {"levenberg-marquardt", "dogleg"}) == "dogleg"
                 ? TrustRegion::Dogleg
                 : TrustRegion::LevenbergMarquardt;
  o.max_iterations = static_cast<int>(t.integer_or("max_iterations", o.max_iterations, 1, 100000));
  o.tolerance = t.number_or("tolerance", o.tolerance, Range::closed(1e-15, 1e-2));
  o.difference_step = t.number_or("difference_step", o.difference_step, Range::closed(1e-12, 1e-2));
  o.starts = static_cast<int>(t.integer_or("starts", o.starts, 1, 1000));
  o.seed = static_cast<unsigned>(t.integer_or("seed", o.seed, 0, 4294967295LL));
  return o;
}

DataUnits read_units(const TableReader& t) {
  const std::string stress = t.choice_or("stress_unit", "Pa", {"Pa", "kPa", "MPa"});
  const std::string strain = t.choice_or("strain_unit", "1", {"1", "percent"});
  return {.stress = stress == "MPa"   ? 1e6
                    : stress == "kPa" ? 1e3
                                      : 1.0,
          .strain = strain == "percent" ? 0.01 : 1.0};
}

/// A column name the driver produces, or a ParameterError naming the key.
std::string column_name(const toml::node* node, const TableReader& t, std::string_view key) {
  const std::optional<std::string> name = node ? node->value_exact<std::string>() : std::nullopt;
  if (!name) t.fail(key, "must be a column name (one of " + point_column_names() + ")");
  if (!point_column(*name))
    t.fail(key,
           "\"" + *name + "\" is not a column the model produces (allowed: " + point_column_names() + ")");
  return *name;
}

Experiment read_experiment(const toml::table& table, const std::string& path, std::size_t index,
                           const MaterialTemplate& material) {
  const std::string label = "experiment " + std::to_string(index + 1);
  const TableReader t(table, path, label);
  Experiment e;
  const auto file = [&](std::string_view key) {
    const std::optional<std::string> name = table[key].value_exact<std::string>();
    if (!name) t.fail(key, "must be a file name");
    t.accept({key});
    const std::string found = beside(path, *name);
    if (!fs::exists(found)) t.fail(key, "\"" + *name + "\": no such file (" + found + ")");
    return found;
  };
  e.programme_path = file("programme");
  const std::string data_path = file("data");
  e.name = t.has("name") ? t.word("name") : fs::path(data_path).stem().string();
  e.where = path + ": [[experiment]] " + std::to_string(index + 1) + " (" + e.name + ")";
  t.accept({"against", "match"});
  const std::string against = column_name(table.get("against"), t, "against");
  const toml::array* list = table["match"].as_array();
  if (!list || list->empty())
    t.fail("match", "must be a non-empty list of column names, e.g. [\"q\", \"u\"]");
  std::vector<std::string> match;
  for (const toml::node& node : *list) {
    const std::string name = column_name(&node, t, "match");
    if (name == against) t.fail("match", "\"" + name + "\" is the driven column (against)");
    if (std::find(match.begin(), match.end(), name) != match.end())
      t.fail("match", "\"" + name + "\" is listed twice");
    match.push_back(name);
  }
  e.weight = t.number_or("weight", 1.0, Range::positive());
  const DataUnits units = read_units(t);
  t.reject_unknown_keys();
  e.data = read_measured_curve(data_path, against, match, units, e.where);
  // The programme must read with the fitted material in place of its own: its file's messages now.
  e.programme = parse_toml_file(e.programme_path);
  experiment_programme(e, material.table);  // its errors are the programme file's, said now
  return e;
}

}  // namespace

verification::ProgrammeFile experiment_programme(const Experiment& e, const toml::table& material) {
  toml::table root = e.programme;
  root.insert_or_assign("material", material);
  // The driver is rate-independent: a relaxation time (a collapse's key) would only be warned about
  // at every run; read_material_template has said it once.
  if (const auto tau = material["viscoplastic_relaxation_time"].value<double>(); tau && *tau > 0.0)
    root["material"].as_table()->insert_or_assign("viscoplastic_relaxation_time", 0.0);
  return verification::read_programme(root, e.programme_path);
}

CalibrationFile read_calibration_file(const std::string& path) {
  const toml::table root = parse_toml_file(path);
  for (const auto& [key, value] : root) {
    if (key.str() != "material" && key.str() != "fit" && key.str() != "experiment")
      throw ParameterError(path + ": " + std::string(key.str()) +
                           " is not a known key or table (allowed: material, [fit], [[experiment]])");
  }
  CalibrationFile file{.path = path, .material = read_material_template(root, path)};
  const toml::table* fit = root["fit"].as_table();
  if (!fit) throw ParameterError(path + ": no [fit] table (parameters = { KEY = [lower, upper], ... })");
  file.parameters = read_parameters(*fit, path, file.material);
  for (const FitParameter& p : file.parameters) file.material.keys.push_back(p.key);
  const TableReader fit_reader(*fit, path, "fit");
  fit_reader.accept({"parameters"});
  file.options = read_options(fit_reader);
  fit_reader.reject_unknown_keys();
  const toml::array* experiments = root["experiment"].as_array();
  if (!experiments || experiments->empty() || !experiments->is_array_of_tables())
    throw ParameterError(path + ": no [[experiment]] tables");
  for (std::size_t k = 0; k < experiments->size(); ++k)
    file.experiments.push_back(read_experiment(*experiments->get(k)->as_table(), path, k, file.material));
  for (std::size_t k = 0; k < file.experiments.size(); ++k)
    for (std::size_t j = 0; j < k; ++j)
      if (file.experiments[j].name == file.experiments[k].name)
        throw ParameterError(file.experiments[k].where + ": the name is that of [[experiment]] " +
                             std::to_string(j + 1) + " too (name = \"...\" tells them apart)");
  return file;
}

}  // namespace soilsph::calibration
