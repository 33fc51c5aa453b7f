#include "constitutive/material.h"

#include <algorithm>
#include <iostream>
#include <vector>

#include "constitutive/derived_constants.h"

namespace soilsph {

namespace {
/// A UMAT plug-in: its library is loaded and called once here, and what goes wrong is said of the file.
UmatModel read_umat(const TableReader& table) {
  const UmatModel::Params params = UmatModel::Params::read(table);
  try {
    return UmatModel(params);
  } catch (const ParameterError& e) {
    throw ParameterError(table.source() + ": [" + table.table_name() + "] " + e.what());
  }
}
}  // namespace

namespace {
template <class... Model>
std::vector<std::string_view> keys_of_models(const std::variant<Model...>*) {
  std::vector<std::string_view> keys{"model"};
  for (const std::vector<std::string_view>& model_keys : {field_keys<typename Model::Params>()...})
    for (const std::string_view key : model_keys)
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
  return keys;
}
}  // namespace

std::span<const std::string_view> material_keys() {
  static const std::vector<std::string_view> keys = keys_of_models(static_cast<const Material*>(nullptr));
  return keys;
}

Material read_material(const TableReader& table) {
  const std::string model =
      table.choice("model", {LinearElastic::kName, DruckerPrager::kName, ModifiedCamClay::kName,
                             MohrCoulomb::kName, UmatModel::kName});
  const Material material = [&]() -> Material {
    try {
      if (model == DruckerPrager::kName) return DruckerPrager(DruckerPrager::Params::read(table));
      if (model == ModifiedCamClay::kName) return ModifiedCamClay(ModifiedCamClay::Params::read(table));
      if (model == MohrCoulomb::kName) return MohrCoulomb(MohrCoulomb::Params::read(table));
      if (model == UmatModel::kName) return read_umat(table);
      return LinearElastic(LinearElastic::Params::read(table));
    } catch (const DerivedConstantError& e) {  // the constructor's check, said of the file's key
      table.fail_value(e.key(), format_number(e.value()), e.reason());
    }
  }();
  // Keys of other models are allowed (one scene can switch models with --set) but said to be unused.
  const std::span<const std::string_view> known = material_keys();
  for (const std::string& key : table.unread_keys()) {
    if (std::find(known.begin(), known.end(), key) == known.end()) table.fail_unknown(key, known);
    std::cerr << "note: " << table.source() << ": [" << table.table_name() << "] " << key
              << " is not used by " << model << '\n';
  }
  return material;
}

std::string material_table_name(std::string_view name) {
  return name.empty() ? "material" : "materials." + std::string(name);
}

const toml::table& material_table(const toml::table& root, const std::string& path, std::string_view name) {
  const toml::table* named = root["materials"].as_table();
  std::string names;  // "clay, sand": the scene's named materials
  if (named)
    for (const auto& [key, node] : *named)
      if (node.is_table()) names.append(names.empty() ? "" : ", ").append(key.str());
  if (name.empty()) {
    if (const toml::table* table = root["material"].as_table()) return *table;
    if (names.empty()) throw ParameterError(path + ": no [material] table");
    const std::string first = names.substr(0, names.find(','));
    throw ParameterError(path + ": no [material] table; it is a scene of named materials (" + names +
                         "): pick one with --material NAME, e.g. --material " + first);
  }
  if (const toml::table* table = named ? (*named)[name].as_table() : nullptr) return *table;
  throw ParameterError("--material " + std::string(name) + ": " + path + " has no [materials." +
                       std::string(name) + "] table (" +
                       (names.empty()
                            ? "it names no materials; leave out --material to read its [material] table"
                            : "its named materials: " + names) +
                       ")");
}

Material load_material(const std::string& path, std::string_view name) {
  const toml::table root = parse_toml_file(path);
  return read_material(TableReader(material_table(root, path, name), path, material_table_name(name)));
}

Material with_integrator(const Material& material, Integrator integrator) {
  return with_edited_params(material, [integrator](auto& params) {
    if constexpr (requires { params.integrator; }) params.integrator = integrator;
  });
}

std::string_view model_name(const Material& material) {
  return std::visit([](const auto& model) { return std::decay_t<decltype(model)>::kName; }, material);
}

double viscoplastic_relaxation_time(const Material& material) {
  return std::visit(
      [](const auto& model) {
        if constexpr (requires { model.params().viscoplastic_relaxation_time; })
          return model.params().viscoplastic_relaxation_time;
        return 0.0;
      },
      material);
}

double density(const Material& material) {
  return std::visit([](const auto& model) { return model.params().density; }, material);
}

bool has_rate_form(const Material& material) {
  return !std::holds_alternative<UmatModel>(material);
}

bool has_preconsolidation(const Material& material) {
  return std::visit([](const auto& model) { return std::decay_t<decltype(model)>::kHasPreconsolidation; },
                    material);
}

namespace {
template <class... Model>
std::string names_with_preconsolidation(const std::variant<Model...>*) {
  std::vector<std::string_view> names;
  ((Model::kHasPreconsolidation ? names.push_back(Model::kName) : void()), ...);
  std::string list;
  for (const std::string_view name : names) list.append(list.empty() ? "" : ", ").append(name);
  return list;
}
}  // namespace

std::string preconsolidation_models() {
  return names_with_preconsolidation(static_cast<const Material*>(nullptr));
}

double initial_preconsolidation(const Material& material, const Mat3& sigma, double ocr) {
  return std::visit([&](const auto& model) { return model.initial_preconsolidation(sigma, ocr); }, material);
}

std::optional<FailureLine> triaxial_failure_line(const Material& material) {
  return std::visit(
      [](const auto& model) -> std::optional<FailureLine> {
        if constexpr (PlasticModel<std::decay_t<decltype(model)>>)
          return model.triaxial_failure_line();
        else
          return std::nullopt;
      },
      material);
}

}  // namespace soilsph
