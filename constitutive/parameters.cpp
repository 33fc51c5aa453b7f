#include "constitutive/parameters.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace soilsph {

std::string format_number(double x) {
  std::ostringstream out;
  out << x;
  std::string text = out.str();
  const auto e = text.find('e');
  if (e == std::string::npos) return text;
  // "1e+07" → "1e7", "1e-07" → "1e-7".
  std::size_t digits = e + 1;
  if (text[digits] == '+')
    text.erase(digits, 1);
  else if (text[digits] == '-')
    ++digits;
  while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
  return text;
}

std::string exact_number(double x) {
  // Plain digits where they are short (100000, not 1e+05), else the shortest form.
  char buffer[400];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed);
  if (result.ec == std::errc() && result.ptr - buffer <= 12) return std::string(buffer, result.ptr);
  result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

void FieldDescriber::add(std::string_view key, std::string value, Listed listed) const {
  if (listed == Listed::WhenSet && defaults_) {
    for (const auto& [default_key, default_value] : *defaults_)
      if (default_key == key && default_value == value) return;
  }
  out_.emplace_back(key, std::move(value));
}

namespace {
/// `text` as a TOML basic string.
std::string toml_quoted(std::string_view text) {
  std::ostringstream out;
  out << toml::value<std::string>(std::string(text));
  return out.str();
}
/// "text" in messages, as the file holds it.
std::string double_quoted(std::string_view text) {
  std::string out(1, '"');
  return out.append(text).append(1, '"');
}
/// [1, 0.5]: numbers as a TOML array that reads back to them.
std::string toml_array(const std::vector<double>& values) {
  std::string list;
  for (const double v : values) list.append(list.empty() ? "" : ", ").append(exact_number(v));
  return "[" + list + "]";
}
/// "a", "b", "c": the allowed names in messages.
std::string quoted_list(std::span<const std::string_view> names) {
  std::string list;
  for (std::string_view name : names) list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  return list;
}
}  // namespace

std::string Length::describe() const {
  const auto characters = [](std::size_t n) {
    return std::to_string(n) + (n == 1 ? " character" : " characters");
  };
  if (max == std::numeric_limits<std::size_t>::max())
    return min == 0 ? "any text" : "at least " + characters(min);
  if (min == 0) return "at most " + characters(max);
  return characters(min) + " to " + characters(max);
}

std::string Count::describe() const {
  if (!none_or) return "any number of values";
  return "0 or " + std::to_string(*none_or) + " values, as " + std::string(set_by) + " = " +
         std::to_string(*none_or);
}

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  if (or_zero && x == 0.0) return true;
  const bool above = lower_open ? x > lower : x >= lower;
  const bool below = upper_open ? x < upper : x <= upper;
  return above && below;
}

std::string Range::describe() const {
  std::string text;
  if (std::isfinite(lower)) text += format_number(lower) + (lower_open ? " < " : " <= ");
  text += "value";
  if (std::isfinite(upper)) text += (upper_open ? " < " : " <= ") + format_number(upper);
  if (!std::isfinite(lower) && !std::isfinite(upper)) text = "any finite value";
  return or_zero ? "value = 0 or " + text : text;
}

TableReader::TableReader(const toml::table& table, std::string source, std::string table_name)
    : table_(table), source_(std::move(source)), table_name_(std::move(table_name)) {}

std::string TableReader::where(std::string_view key) const {
  // A value that --set put in the table carries that option as its source (apply_override), so the
  // message blames the option instead of a file that never held the value.
  std::string source = source_;
  if (const toml::node* node = table_.get(key);
      node && node->source().path && node->source().path->starts_with(kOverridePrefix))
    source = *node->source().path;
  return source + ": [" + table_name_ + "] " + std::string(key);
}

void TableReader::fail(std::string_view key, std::string_view what) const {
  throw ParameterError(where(key) + ": " + std::string(what));
}

void TableReader::fail_value(std::string_view key, std::string_view value, std::string_view what) const {
  throw ParameterError(where(key) + " = " + std::string(value) + " " + std::string(what));
}

const toml::node* TableReader::find(std::string_view key) const {
  used_.emplace(key);
  return table_.get(key);
}

bool TableReader::has(std::string_view key) const {
  return table_.get(key) != nullptr;
}

double TableReader::number(std::string_view key, Range range, std::string_view unit) const {
  const toml::node* node = find(key);
  if (!node)
    fail(key,
         "is missing (allowed: " + range.describe() + (unit.empty() ? "" : " ") + std::string(unit) + ")");
  const std::optional<double> value = node->value<double>();
  if (!value || node->is_boolean()) fail(key, "must be a number");
  if (!range.contains(*value)) {
    fail_value(key, format_number(*value),
               "is out of range (allowed: " + range.describe() + (unit.empty() ? "" : " ") +
                   std::string(unit) + ")");
  }
  record(key, *value);
  return *value;
}

void FieldChecker::number(std::string_view key, const double& field, Range range,
                          std::string_view unit) const {
  if (range.contains(field)) return;
  throw ParameterError(std::string(owner_) + " parameters: " + std::string(key) + " = " +
                       format_number(field) + " is out of range (allowed: " + range.describe() +
                       (unit.empty() ? "" : " ") + std::string(unit) + ")");
}

void FieldChecker::fail(std::string_view key, std::string_view value, std::string_view what) const {
  throw ParameterError(std::string(owner_) + " parameters: " + std::string(key) + " = " + std::string(value) +
                       " " + std::string(what));
}

void FieldChecker::text_or(std::string_view key, const std::string& field, Length length) const {
  if (!length.contains(field.size()))
    fail(key, double_quoted(field),
         "has " + std::to_string(field.size()) + " characters (allowed: " + length.describe() + ")");
}

void FieldChecker::file(std::string_view key, const std::string& field) const {
  if (!std::filesystem::is_regular_file(field)) fail(key, double_quoted(field), "is not a file");
}

void FieldChecker::integer_or(std::string_view key, const int& field, int lo, int hi) const {
  if (field < lo || field > hi)
    fail(key, std::to_string(field),
         "is out of range (allowed: " + std::to_string(lo) + " <= value <= " + std::to_string(hi) + ")");
}

void FieldChecker::numbers_or(std::string_view key, const std::vector<double>& field, Range range,
                              Count count, Listed) const {
  if (!count.contains(field.size()))
    fail(key, toml_array(field),
         "has " + std::to_string(field.size()) + " values (allowed: " + count.describe() + ")");
  for (std::size_t k = 0; k < field.size(); ++k)
    if (!range.contains(field[k]))
      fail(key, toml_array(field),
           "has element " + std::to_string(k + 1) + " = " + format_number(field[k]) +
               " out of range (allowed: " + range.describe() + ")");
}

void FieldReader::numbers_or(std::string_view key, std::vector<double>& field, Range range, Count count,
                             Listed) const {
  field = table_.numbers_or(key, field, range);
  if (!count.contains(field.size()))
    table_.fail(key, "has " + std::to_string(field.size()) + " values (allowed: " + count.describe() + ")");
}

void FieldDescriber::numbers_or(std::string_view key, const std::vector<double>& field, Range, Count,
                                Listed listed) const {
  add(key, toml_array(field), listed);
}

double TableReader::number_or(std::string_view key, double fallback, Range range,
                              std::string_view unit) const {
  if (has(key)) return number(key, range, unit);
  used_.emplace(key);
  record(key, fallback);
  return fallback;
}

long long TableReader::integer_or(std::string_view key, long long fallback, long long lo,
                                  long long hi) const {
  const toml::node* node = find(key);
  if (!node) {
    record(key, fallback);
    return fallback;
  }
  const std::optional<long long> value = node->value_exact<long long>();
  if (!value) fail(key, "must be an integer");
  if (*value < lo || *value > hi) {
    fail_value(
        key, std::to_string(*value),
        "is out of range (allowed: " + std::to_string(lo) + " <= value <= " + std::to_string(hi) + ")");
  }
  record(key, *value);
  return *value;
}

bool TableReader::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* node = find(key);
  const std::optional<bool> value = node ? node->value_exact<bool>() : fallback;
  if (!value) fail(key, "must be true or false");
  record(key, *value);
  return *value;
}

std::string TableReader::choice(std::string_view key, std::span<const std::string_view> allowed) const {
  const std::string options = quoted_list(allowed);
  const toml::node* node = find(key);
  if (!node) fail(key, "is missing (allowed: " + options + ")");
  const std::optional<std::string> value = node->value_exact<std::string>();
  if (!value) fail(key, "must be a string (allowed: " + options + ")");
  for (std::string_view a : allowed) {
    if (*value == a) {
      record(key, *value);
      return *value;
    }
  }
  fail_value(key, "\"" + *value + "\"", "is not allowed (allowed: " + options + ")");
}

std::string TableReader::string_or(std::string_view key, std::string_view fallback) const {
  const toml::node* node = find(key);
  if (!node) {
    record(key, std::string(fallback));
    return std::string(fallback);
  }
  const std::optional<std::string> value = node->value_exact<std::string>();
  if (!value) fail(key, "must be a string");
  record(key, *value);
  return *value;
}

std::string TableReader::text_or(std::string_view key, std::string_view fallback, Length length) const {
  const std::string text = string_or(key, fallback);
  if (!length.contains(text.size()))
    fail_value(key, double_quoted(text),
               "has " + std::to_string(text.size()) + " characters (allowed: " + length.describe() + ")");
  return text;
}

std::string TableReader::file(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) fail(key, "is missing (allowed: the path of a file, absolute or relative to this file)");
  const std::optional<std::string> text = node->value_exact<std::string>();
  if (!text || text->empty()) fail(key, "must be the path of a file, absolute or relative to this file");
  record(key, *text);
  namespace fs = std::filesystem;
  const fs::path path =
      fs::path(*text).is_absolute() ? fs::path(*text) : fs::path(source_).parent_path() / *text;
  if (!fs::is_regular_file(path))
    fail_value(key, double_quoted(*text), "is not a file (" + path.string() + ")");
  return fs::absolute(path).lexically_normal().string();
}

std::vector<double> TableReader::numbers_or(std::string_view key, std::span<const double> fallback,
                                            Range range) const {
  const toml::node* node = find(key);
  std::vector<double> values(fallback.begin(), fallback.end());
  if (node) {
    const toml::array* array = node->as_array();
    if (!array) fail(key, "must be an array of numbers (allowed: " + range.describe() + ")");
    values.clear();
    for (std::size_t k = 0; k < array->size(); ++k) {
      const toml::node& element = *array->get(k);
      const std::optional<double> value = element.value<double>();
      const std::string position = "element " + std::to_string(k + 1);
      if (!value || element.is_boolean()) fail(key, position + " must be a number");
      if (!range.contains(*value))
        fail(key, position + " = " + format_number(*value) +
                      " is out of range (allowed: " + range.describe() + ")");
      values.push_back(*value);
    }
  }
  toml::array resolved;
  for (const double v : values) resolved.push_back(v);
  record(key, std::move(resolved));
  return values;
}

std::string TableReader::word(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) fail(key, "is missing (a name of letters, digits, '_' and '-')");
  const std::optional<std::string> value = node->value_exact<std::string>();
  const bool word = value && !value->empty() &&
                    std::all_of(value->begin(), value->end(),
                                [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; });
  if (!word) fail(key, "must be a name of letters, digits, '_' and '-' (it labels output rows)");
  record(key, *value);
  return *value;
}

std::string TableReader::choice_or(std::string_view key, std::string_view fallback,
                                   std::span<const std::string_view> allowed) const {
  if (has(key)) return choice(key, allowed);
  used_.emplace(key);
  record(key, std::string(fallback));
  return std::string(fallback);
}

std::vector<std::string> TableReader::choices_or(std::string_view key,
                                                 std::span<const std::string_view> fallback,
                                                 std::span<const std::string_view> allowed) const {
  const std::string options = quoted_list(allowed);
  const toml::node* node = find(key);
  const auto recorded = [&](std::vector<std::string> names) {
    toml::array array;
    for (const std::string& name : names) array.push_back(name);
    record(key, std::move(array));
    return names;
  };
  if (!node) return recorded({fallback.begin(), fallback.end()});
  const toml::array* array = node->as_array();
  if (!array)
    fail(key, "must be an array of names, e.g. [\"" + std::string(allowed.front()) +
                  "\"] (allowed: " + options + ")");
  std::vector<std::string> names;
  for (const toml::node& element : *array) {
    const std::optional<std::string> value = element.value_exact<std::string>();
    if (!value) fail(key, "must hold only strings (allowed: " + options + ")");
    bool known = false;
    for (std::string_view a : allowed) known = known || *value == a;
    if (!known) fail(key, "\"" + *value + "\" is not allowed (allowed: " + options + ")");
    for (const std::string& earlier : names) {
      if (earlier == *value) fail(key, "\"" + *value + "\" is listed twice (allowed: " + options + ")");
    }
    names.push_back(*value);
  }
  return recorded(std::move(names));
}

void TableReader::accept(std::initializer_list<std::string_view> keys) const {
  for (std::string_view k : keys) used_.emplace(k);
}

std::vector<std::string> TableReader::unread_keys() const {
  std::vector<std::string> keys;
  for (const auto& [key, node] : table_) {
    if (!used_.contains(key.str())) keys.emplace_back(key.str());
  }
  return keys;
}

void TableReader::fail_unknown(std::string_view key, std::span<const std::string_view> known) const {
  const std::optional<std::string_view> nearest = nearest_key(key, known);
  fail(key, "is not a known key" +
                (nearest ? " (did you mean \"" + std::string(*nearest) + "\"?)" : std::string()));
}

void TableReader::reject_unknown_keys() const {
  const std::vector<std::string> unknown = unread_keys();
  if (unknown.empty()) return;
  // Every key a reader asks for (read, defaulted or accepted) is a known one.
  const std::vector<std::string_view> known(used_.begin(), used_.end());
  fail_unknown(unknown.front(), known);
}

namespace {
/// The optimal string alignment distance: the fewest insertions, deletions, substitutions and
/// swaps of two neighbouring characters that turn `a` into `b` (Wagner–Fischer's table with
/// Damerau's transposition, no substring edited twice).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}
}  // namespace

std::optional<std::string_view> nearest_key(std::string_view key, std::span<const std::string_view> known) {
  std::optional<std::string_view> nearest;
  std::size_t best = std::min<std::size_t>(2, key.size() / 3);
  for (const std::string_view candidate : known) {
    const std::size_t distance = edit_distance(key, candidate);
    if (distance <= best && (!nearest || distance < best)) {
      nearest = candidate;
      best = distance;
    }
  }
  return nearest;
}

toml::table parse_toml_file(const std::string& path) {
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw ParameterError(path + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) + ": " +
                         std::string(e.description()));
  }
}

void apply_override(toml::table& root, std::string_view assignment) {
  const std::size_t eq = assignment.find('=');
  const std::size_t dot = assignment.find('.');
  if (eq == std::string_view::npos || dot == std::string_view::npos || dot > eq) {
    throw ParameterError("--set " + std::string(assignment) + ": expected section.key=value");
  }
  const std::string option = "--set " + std::string(assignment);
  // The key path: tables by name and the entries of an array of tables ([[regions]], ...) by their
  // number from 1, as messages label them ("[regions #2]"); the last name is the key set. A table
  // named on the way that does not exist is created.
  std::vector<std::string> path;
  for (std::size_t from = 0;;) {
    const std::size_t to = std::min(assignment.find('.', from), eq);
    path.emplace_back(assignment.substr(from, to - from));
    // Also the name after a last dot: "material.=1" names no key (it once set [material] itself).
    if (path.back().empty()) throw ParameterError(option + ": an empty name in the key path");
    if (to == eq) break;
    from = to + 1;
  }
  const std::string key = path.back();
  path.pop_back();
  const std::string dotted(assignment.substr(0, eq)), text(assignment.substr(eq + 1));
  toml::node* node = &root;
  std::string where;
  for (const std::string& name : path) {
    if (toml::array* array = node->as_array()) {
      std::size_t k = 0;
      const auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), k);
      if (ec != std::errc() || end != name.data() + name.size() || k < 1 || k > array->size())
        throw ParameterError(option + ": [[" + where + "]] has " + std::to_string(array->size()) +
                             " entries; name one by its number from 1 (" + where + ".1." + key + "=...)");
      node = &(*array)[k - 1];
      where += " #" + name;
    } else {
      toml::table& table = *node->as_table();
      node = table.get(name);
      if (!node) node = &table.insert_or_assign(name, toml::table{}).first->second;
      where += (where.empty() ? "" : ".") + name;
    }
    if (!node->is_table() && !node->is_array())
      throw ParameterError(option + ": [" + where + "] is not a table");
  }
  toml::table* table = node->as_table();
  if (!table)
    throw ParameterError(option + ": [[" + where +
                         "]] is an array of tables; name an entry by its number from 1 (" + where + ".1." +
                         key + "=...)");
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text, std::string(kOverridePrefix) + std::string(assignment));
  } catch (const toml::parse_error& e) {
    // An array or inline table must be valid TOML: `[p,q]` is what a shell leaves of ["p","q"].
    if (text.starts_with('[') || text.starts_with('{')) {
      throw ParameterError("--set " + std::string(assignment) + ": not a TOML value (" +
                           std::string(e.description()) +
                           "); strings inside an array need double quotes, which the shell keeps "
                           "inside single quotes: --set '" +
                           dotted + "=[\"a\",\"b\"]'");
    }
    // A bare word such as modified-cam-clay is a string; it is parsed as one so that it, too,
    // carries the option as its source.
    parsed = toml::parse("v = " + toml_quoted(text), std::string(kOverridePrefix) + std::string(assignment));
  }
  // Moved, not copied: a copied node loses its source, which messages use to name the option.
  table->insert_or_assign(key, std::move(*parsed.get("v")));
}

std::string overrides_note(std::span<const std::string> overrides) {
  std::string list;
  for (const std::string& assignment : overrides) list += (list.empty() ? "" : ", ") + assignment;
  return list.empty() ? "" : " [with --set " + list + "]";
}

}  // namespace soilsph
