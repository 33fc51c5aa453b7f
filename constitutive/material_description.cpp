#include "constitutive/material_description.h"

#include <utility>

namespace soilsph {

namespace {
using Parameters = std::vector<std::pair<std::string, std::string>>;

/// `model`, then the fields of the model's Params in the order of its fields() list.
template <class Model>
Parameters parameters(const Model& m) {
  std::string model(1, '"');  // appended, not `"\"" + ...`: GCC 12 warns falsely of that (-Wrestrict)
  model.append(Model::kName).append(1, '"');
  Parameters out{{"model", std::move(model)}};
  for (auto& key_value : described_fields(m.params())) out.push_back(std::move(key_value));
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
