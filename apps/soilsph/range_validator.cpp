#include "apps/soilsph/range_validator.h"

#include <charconv>
#include <cmath>
#include <optional>

namespace soilsph::cli {

namespace {
/// The whole of `text` as a number, or nothing.
std::optional<double> parse_number(const std::string& text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::string allowed(const Range& range, std::string_view unit) {
  return " (allowed: " + range.describe() + (unit.empty() ? "" : " ") + std::string(unit) + ")";
}
}  // namespace

CLI::Validator in_range(const Range& range, std::string_view unit) {
  const std::string bounds = allowed(range, unit);
  return CLI::Validator(
      [range, bounds](std::string& text) -> std::string {
        const std::optional<double> value = parse_number(text);
        if (!value) return text + " is not a number" + bounds;
        if (!range.contains(*value)) return text + " is out of range" + bounds;
        return "";
      },
      range.describe() + (unit.empty() ? "" : " ") + std::string(unit));
}

CLI::Validator whole_number_in(long long lo, long long hi) {
  const Range range = Range::closed(static_cast<double>(lo), static_cast<double>(hi));
  const std::string bounds = allowed(range, "");
  return CLI::Validator(
      [range, bounds](std::string& text) -> std::string {
        const std::optional<double> value = parse_number(text);
        if (!value || *value != std::floor(*value)) return text + " is not a whole number" + bounds;
        if (!range.contains(*value)) return text + " is out of range" + bounds;
        text = std::to_string(static_cast<long long>(*value));  // e.g. 1e3 → 1000, which CLI11 converts
        return "";
      },
      range.describe());
}

CLI::Validator list_in_range(const Range& range, std::string_view unit) {
  const CLI::Validator item = in_range(range, unit);
  return CLI::Validator(
      [item](std::string& text) -> std::string {
        std::size_t start = 0;
        for (;;) {
          const std::size_t comma = text.find(',', start);
          std::string value = text.substr(start, comma - start);
          if (value.empty()) return "an empty item in " + text + " (give numbers separated by single commas)";
          if (std::string why = item(value); !why.empty()) return why;
          if (comma == std::string::npos) return "";
          start = comma + 1;
        }
      },
      "list of " + item.get_description());
}

std::vector<double> split_numbers(const std::string& list) {
  std::vector<double> numbers;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = list.find(',', start);
    numbers.push_back(parse_number(list.substr(start, comma - start)).value());
    if (comma == std::string::npos) return numbers;
    start = comma + 1;
  }
}

}  // namespace soilsph::cli
