#include "verification/calibration/material_values.h"

#include <charconv>

namespace soilsph::calibration {

namespace {

/// `name(N)` split into the array's name and N − 1; nullopt for a plain key or a malformed index.
std::optional<std::pair<std::string_view, std::size_t>> array_element(std::string_view key) {
  const std::size_t open = key.find('(');
  if (open == std::string_view::npos || open == 0 || key.back() != ')') return std::nullopt;
  const std::string_view digits = key.substr(open + 1, key.size() - open - 2);
  std::size_t n = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (error != std::errc() || end != digits.data() + digits.size() || n == 0) return std::nullopt;
  return std::pair{key.substr(0, open), n - 1};
}

toml::node* number_at(toml::table& table, std::string_view key) {
  if (const auto element = array_element(key)) {
    toml::array* array = table[element->first].as_array();
    return array ? array->get(element->second) : nullptr;
  }
  return table.get(key);
}

}  // namespace

const toml::node* parameter_node(const toml::table& table, std::string_view key) {
  const toml::node* node = number_at(const_cast<toml::table&>(table), key);
  return node && node->is_number() ? node : nullptr;
}

toml::table MaterialTemplate::with(std::span<const double> values) const {
  toml::table rewritten = table;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (const auto element = array_element(keys[k])) {
      toml::array& array = *rewritten[element->first].as_array();
      array.replace(array.cbegin() + static_cast<std::ptrdiff_t>(element->second), values[k]);
    } else {
      rewritten.insert_or_assign(keys[k], values[k]);
    }
  }
  return rewritten;
}

Material MaterialTemplate::build(std::span<const double> values) const {
  const toml::table rewritten = with(values);
  return read_material(TableReader(rewritten, source, "material"));
}

std::string numeric_keys(const toml::table& table) {
  std::string list;
  const auto add = [&list](const std::string& key) { list.append(list.empty() ? "" : ", ").append(key); };
  for (const auto& [key, value] : table) {
    if (value.is_number()) add(std::string(key.str()));
    if (const toml::array* array = value.as_array();
        array && !array->empty() && array->is_homogeneous<double>())
      add(std::string(key.str()) + "(1)" +
          (array->size() > 1 ? " to " + std::string(key.str()) + "(" + std::to_string(array->size()) + ")"
                             : ""));
  }
  return list;
}

}  // namespace soilsph::calibration
