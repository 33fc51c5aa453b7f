#pragma once
/// @file
/// The input names of an enum, written once: one table of (value, name) pairs per enum, read in both
/// directions (name_of, parse_name) and by the messages that list the allowed names (names_of), so a
/// value added to the table is printed, parsed and offered alike.
///
///   inline constexpr auto kColourTable = enum_table<Colour>({{Colour::Red, "red"}, {Colour::Blue, "blue"}});
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace soilsph {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <class Enum, std::size_t N>
using EnumTable = std::array<EnumName<Enum>, N>;

/// A table from a braced list, its size counted.
template <class Enum, std::size_t N>
constexpr EnumTable<Enum, N> enum_table(const EnumName<Enum> (&entries)[N]) {
  EnumTable<Enum, N> table{};
  for (std::size_t k = 0; k < N; ++k) table[k] = entries[k];
  return table;
}

/// The name of `value` ("unknown" for a value the table lacks, which a complete table never meets).
template <class Enum, std::size_t N>
constexpr std::string_view name_of(const EnumTable<Enum, N>& table, Enum value) {
  for (const EnumName<Enum>& entry : table)
    if (entry.value == value) return entry.name;
  return "unknown";
}

/// The value named `name`; none for a name the table lacks.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> parse_name(const EnumTable<Enum, N>& table, std::string_view name) {
  for (const EnumName<Enum>& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

/// The names in table order: what a key allows (TableReader::choice) and what messages list.
template <class Enum, std::size_t N>
constexpr std::array<std::string_view, N> names_of(const EnumTable<Enum, N>& table) {
  std::array<std::string_view, N> names{};
  for (std::size_t k = 0; k < N; ++k) names[k] = table[k].name;
  return names;
}

/// The values in table order, for loops over every value.
template <class Enum, std::size_t N>
constexpr std::array<Enum, N> values_of(const EnumTable<Enum, N>& table) {
  std::array<Enum, N> values{};
  for (std::size_t k = 0; k < N; ++k) values[k] = table[k].value;
  return values;
}

}  // namespace soilsph
