#include "constitutive/material_description.h"

#include <utility>

namespace soilsph {

namespace {
using Parameters = std::vector<std::pair<std::string, std::string>>;

std::string number(double x) {
  return exact_number(x);
}
std::string quoted(std::string_view text) {
  return "\"" + std::string(text) + "\"";
}

/// `model`, then the fields of the model's Params in the order of its fields() list.
template <class Model>
Parameters parameters(const Model& m) {
  Parameters out{{"model", quoted(Model::kName)}};
  for (auto& key_value : described_fields(m.params())) out.push_back(std::move(key_value));
  return out;
}

std::string numbers(const std::vector<double>& values) {
  std::string list;
  for (const double v : values) list += (list.empty() ? "" : ", ") + number(v);
  return "[" + list + "]";
}
/// A UMAT plug-in: its keys as UmatParams::read reads them.
Parameters parameters(const UmatModel& m) {
  const auto& p = m.params();
  Parameters out{{"model", quoted(UmatModel::kName)}, {"density", number(p.density)}};
  out.emplace_back("library", quoted(p.library));
  out.emplace_back("symbol", quoted(p.symbol));
  out.emplace_back("name", quoted(p.name));
  out.emplace_back("props", numbers(p.props));
  out.emplace_back("state_variables", std::to_string(p.state_variables));
  if (!p.initial_state.empty()) out.emplace_back("initial_state", numbers(p.initial_state));
  out.emplace_back("stress_unit", quoted(name_of(kStressUnitTable, p.stress_unit)));
  out.emplace_back("thread_safe", p.thread_safe ? "true" : "false");
  return out;
}
}  // namespace

std::vector<std::pair<std::string, std::string>> material_parameters(const Material& material) {
  return std::visit([](const auto& model) { return parameters(model); }, material);
}

std::string describe_material(const Material& material) {
  std::string line;
  for (const auto& [key, value] : material_parameters(material))
    line += (line.empty() ? "" : "; ") + key + " = " + value;
  return line;
}

}  // namespace soilsph
