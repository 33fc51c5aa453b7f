#include "verification/calibration/material_values.h"

namespace soilsph::calibration {

toml::table MaterialTemplate::with(std::span<const double> values) const {
  toml::table rewritten = table;
  for (std::size_t k = 0; k < keys.size(); ++k) rewritten.insert_or_assign(keys[k], values[k]);
  return rewritten;
}

Material MaterialTemplate::build(std::span<const double> values) const {
  const toml::table rewritten = with(values);
  return read_material(TableReader(rewritten, source, "material"));
}

std::string numeric_keys(const toml::table& table) {
  std::string list;
  for (const auto& [key, value] : table)
    if (value.is_number()) list.append(list.empty() ? "" : ", ").append(key.str());
  return list;
}

}  // namespace soilsph::calibration
