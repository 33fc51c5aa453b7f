#include "apps/soilsph/pressure_option.h"

#include <array>
#include <charconv>
#include <utility>

namespace soilsph::cli {

namespace {
/// Each unit with the power of ten that takes it to Pa.
constexpr std::array<std::pair<std::string_view, int>, 4> kUnits{
    {{"GPa", 9}, {"MPa", 6}, {"kPa", 3}, {"Pa", 0}}};

/// The whole of `text` as a number, or nothing.
std::optional<double> parse_number(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

/// `number` (decimal, possibly with its own exponent: "1.5", "2e-1") times 10^power, converted once:
/// "0.1" with power 6 is read as "0.1e6", so that the result is the double nearest the decimal value.
std::optional<double> scaled(std::string_view number, int power) {
  if (power == 0) return parse_number(number);
  const std::size_t e = number.find_first_of("eE");
  long long exponent = 0;
  if (e != std::string_view::npos) {
    const std::string_view digits = number.substr(e + 1);
    const char* first = digits.data() + (digits.starts_with('+') ? 1 : 0);
    const auto [end, ec] = std::from_chars(first, digits.data() + digits.size(), exponent);
    if (ec != std::errc() || end != digits.data() + digits.size() || first == end) return std::nullopt;
    number = number.substr(0, e);
  }
  // The mantissa alone must be a number: "e5" or "1e" are not.
  if (number.empty() || !parse_number(number)) return std::nullopt;
  return parse_number(std::string(number) + "e" + std::to_string(exponent + power));
}
}  // namespace

std::optional<double> parse_pressure(std::string_view text) {
  for (const auto& [unit, power] : kUnits)
    if (text.ends_with(unit)) return scaled(text.substr(0, text.size() - unit.size()), power);
  return parse_number(text);
}

CLI::Validator pressure_in(const Range& range) {
  const std::string allowed = " (allowed: " + range.describe() + " Pa)";
  const std::string units =
      " (give a number and a unit: " + std::string(kPressureUnits) + ", e.g. 100kPa; a plain number is Pa)";
  return CLI::Validator(
      [range, allowed, units](std::string& text) -> std::string {
        const std::optional<double> pa = parse_pressure(text);
        if (!pa) return text + " is not a pressure" + units;
        if (!range.contains(*pa)) return text + " is out of range" + allowed;
        char buffer[32];
        const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, *pa);  // shortest round trip
        text.assign(buffer, end);
        return "";
      },
      range.describe() + " Pa");
}

}  // namespace soilsph::cli
