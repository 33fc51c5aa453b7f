#include "verification/report/verification_case.h"

#include <algorithm>
#include <set>

#include "constitutive/parameters.h"
#include "verification/closed_form/closed_form.h"

namespace soilsph::verification {

namespace {
namespace fs = std::filesystem;

constexpr std::string_view kPathChoices[] = {"triaxial-drained", "triaxial-undrained", "oedometer",
                                             "isotropic"};

std::string required_string(const toml::table& table, const TableReader& reader, std::string_view key) {
  reader.accept({key});
  const auto value = table[key].value<std::string>();
  if (!value || value->empty()) reader.fail(key, "must be a non-empty string");
  return *value;
}

std::vector<double> strain_targets(const toml::table& table, const TableReader& reader) {
  reader.accept({"strain_targets"});
  const toml::array* array = table["strain_targets"].as_array();
  if (!array || array->empty()) reader.fail("strain_targets", "must be a non-empty array of strains");
  std::vector<double> targets;
  for (const toml::node& node : *array) {
    const auto value = node.value<double>();
    if (!value || std::abs(*value) >= 1.0)
      reader.fail("strain_targets", "entries must be numbers with |value| < 1");
    targets.push_back(*value);
  }
  return targets;
}

std::vector<std::pair<std::string, double>> tolerances(const toml::table& table, const TableReader& reader,
                                                       bool umat) {
  reader.accept({"tolerance"});
  const toml::table* tolerance = table["tolerance"].as_table();
  if (!tolerance || tolerance->empty())
    reader.fail("tolerance", "must be a table of integrator = maximum relative error, e.g. { cvode = 1e-5 }");
  std::vector<std::pair<std::string, double>> out;
  const TableReader inner(*tolerance, reader.source(), reader.table_name() + ".tolerance");
  for (const auto& [key, node] : *tolerance) {
    const std::string name(key.str());
    if (umat != (name == kUmatRun))
      inner.fail(name,
                 umat ? "does not apply to a umat material, which runs its own update: tolerance = { umat = "
                        "... } (no CVODE reference: a UMAT exposes no rate equations)"
                      : "applies to a umat material only");
    if (!umat && name != kReferenceIntegrator) {
      try {
        parse_integrator(name);
      } catch (const std::invalid_argument&) {
        std::string allowed(kReferenceIntegrator);
        for (std::string_view n : kIntegratorNames) allowed += ", " + std::string(n);
        inner.fail(name, "is not an integrator (allowed: " + allowed + ")");
      }
    }
    out.emplace_back(name, inner.number(name, Range::positive()));
  }
  return out;
}

VerificationCase read_case(const toml::table& table, const fs::path& file, std::size_t index) {
  const TableReader reader(table, file.string(), "case[" + std::to_string(index) + "]");
  const std::string name = required_string(table, reader, "name");
  if (!std::all_of(name.begin(), name.end(),
                   [](char ch) { return std::isalnum(ch) || ch == '-' || ch == '_'; }))
    reader.fail("name", "may hold letters, digits, '-' and '_' only (it names output files)");
  const std::string material_file =
      (file.parent_path() / required_string(table, reader, "material")).lexically_normal().string();
  VerificationCase c{name, file.string(), material_file, load_material(material_file), PointTest{}, "none",
                     {},   std::nullopt};
  c.test.path = parse_load_path(reader.choice("path", kPathChoices));
  c.test.p_initial = reader.number_or("p_initial", 100e3, point_limits::p_initial(), "Pa");
  c.test.ocr = reader.number_or("ocr", 1.0, point_limits::ocr());
  c.test.strain_targets = strain_targets(table, reader);
  c.test.increments = static_cast<int>(reader.integer_or("increments", 100, 1, point_limits::kMaxIncrements));
  c.closed_form = reader.choice_or("closed_form", "none", kClosedFormNames);
  const bool umat = std::holds_alternative<UmatModel>(c.material);
  if (umat && c.closed_form != "none")
    c.closed_form_material =
        load_material((file.parent_path() / required_string(table, reader, "closed_form_material"))
                          .lexically_normal()
                          .string());
  if (c.closed_form != "none") {
    try {  // the closed form's own checks (model, elasticity, path, OCR range) at its initial state
      const std::vector<double> start = {0.0};
      closed_form_curve(c.closed_form, c.closed_form_source(), c.test, start);
    } catch (const std::exception& e) {
      reader.fail("closed_form", e.what());
    }
  }
  c.tolerances = tolerances(table, reader, umat);
  reader.reject_unknown_keys();
  return c;
}
}  // namespace

std::vector<VerificationCase> read_case_file(const fs::path& file) {
  const toml::table root = parse_toml_file(file.string());
  const TableReader top(root, file.string(), "");
  top.accept({"case"});
  top.reject_unknown_keys();
  const toml::array* cases = root["case"].as_array();
  if (!cases || cases->empty()) throw ParameterError(file.string() + ": no [[case]] tables");
  std::vector<VerificationCase> out;
  for (std::size_t i = 0; i < cases->size(); ++i) {
    const toml::table* table = (*cases)[i].as_table();
    if (!table) throw ParameterError(file.string() + ": case " + std::to_string(i) + " is not a table");
    out.push_back(read_case(*table, file, i));
  }
  return out;
}

std::vector<VerificationCase> read_cases(const fs::path& folder) {
  std::vector<fs::path> files;
  if (fs::is_regular_file(folder)) {
    files.push_back(folder);
  } else if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
  }
  if (files.empty()) throw ParameterError(folder.string() + ": no verification case files (*.toml)");
  std::vector<VerificationCase> all;
  std::set<std::string> names;
  for (const fs::path& file : files) {
    for (VerificationCase& c : read_case_file(file)) {
      if (!names.insert(c.name).second)
        throw ParameterError(file.string() + ": case name '" + c.name + "' is used twice");
      all.push_back(std::move(c));
    }
  }
  return all;
}

}  // namespace soilsph::verification
