#pragma once
/// @file
/// Validated reading of one TOML table. Every value is range-checked where it is read, every key
/// that the table holds must be consumed (or declared known), and every error names the file, the
/// key and the allowed range, so that a bad input never crashes or falls back silently.
#include <toml++/toml.h>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "constitutive/enum_names.h"

namespace soilsph {

/// An input error that names the file, the key and what is allowed.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A number for messages: six significant digits as `<<` writes them, but 1e12 and 1e-7 rather
/// than 1e+12 and 1e-07.
std::string format_number(double x);
/// A text that reads back to exactly `x`: plain digits where they are short (100000, 0.3), else the
/// shortest form (1e-12, 1.5e+20).
std::string exact_number(double x);

/// An interval of admissible values; each end open or closed, or unbounded.
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = true;
  bool upper_open = true;
  bool or_zero = false;  ///< 0 is allowed too ("off"), below the interval

  static Range positive() { return {0.0, kInf, true, true}; }                   ///< (0, ∞)
  static Range non_negative() { return {0.0, kInf, false, true}; }              ///< [0, ∞)
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }      ///< (lo, hi)
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }  ///< [lo, hi]
  static Range closed_open(double lo, double hi) { return {lo, hi, false, true}; }
  static Range open_closed(double lo, double hi) { return {lo, hi, true, false}; }  ///< (lo, hi]
  /// 0 ("off") or [lo, hi]: a tolerance whose smallest value is where round-off makes it unreachable.
  static Range zero_or_closed(double lo, double hi) { return {lo, hi, false, false, true}; }

  bool contains(double x) const;
  std::string describe() const;  ///< e.g. "0 < value < 90"

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

/// The admissible length of a string field, in characters.
struct Length {
  std::size_t min = 0;
  std::size_t max = std::numeric_limits<std::size_t>::max();

  static Length any() { return {}; }
  static Length at_least(std::size_t n) { return {n}; }
  static Length at_most(std::size_t n) { return {0, n}; }

  bool contains(std::size_t n) const { return n >= min && n <= max; }
  std::string describe() const;  ///< e.g. "at most 80 characters"
};

/// The admissible number of elements of an array field: any, or none or exactly the value of
/// another key (`set_by`, named in messages).
struct Count {
  std::optional<std::size_t> none_or;  ///< unset: any number
  std::string_view set_by;

  static Count any() { return {}; }
  static Count none_or_exactly(std::size_t n, std::string_view set_by) { return {n, set_by}; }

  bool contains(std::size_t n) const { return !none_or || n == 0 || n == *none_or; }
  std::string describe() const;  ///< e.g. "0 or 4 values, as state_variables = 4"
};

/// Reads the keys of one table (e.g. `[material]`) with validation.
class TableReader {
 public:
  /// @param source file name used in messages; @param table_name the table's dotted name.
  TableReader(const toml::table& table, std::string source, std::string table_name);

  bool has(std::string_view key) const;
  /// A required number in `range`; `unit` is appended to messages ("Pa", "degrees", "").
  double number(std::string_view key, Range range, std::string_view unit = "") const;
  /// An optional number: `fallback` when the key is absent (documented defaults only).
  double number_or(std::string_view key, double fallback, Range range, std::string_view unit = "") const;
  /// An optional integer in [lo, hi].
  long long integer_or(std::string_view key, long long fallback, long long lo, long long hi) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  /// A required string that must be one of `allowed`.
  std::string choice(std::string_view key, std::initializer_list<std::string_view> allowed) const {
    return choice(key, std::span(allowed.begin(), allowed.size()));
  }
  std::string choice(std::string_view key, std::span<const std::string_view> allowed) const;
  std::string choice_or(std::string_view key, std::string_view fallback,
                        std::span<const std::string_view> allowed) const;
  std::string choice_or(std::string_view key, std::string_view fallback,
                        std::initializer_list<std::string_view> allowed) const {
    return choice_or(key, fallback, std::span(allowed.begin(), allowed.size()));
  }
  /// An optional string of any content; `fallback` when the key is absent.
  std::string string_or(std::string_view key, std::string_view fallback) const;
  /// An optional string of `length` characters; `fallback` when the key is absent.
  std::string text_or(std::string_view key, std::string_view fallback, Length length) const;
  /// A required path of an existing file, absolute or relative to the directory of the table's
  /// file; returned absolute and normalised.
  std::string file(std::string_view key) const;
  /// An optional array of numbers, each in `range`; `fallback` when the key is absent. An element
  /// that is not a number or is out of range is an error naming its position.
  std::vector<double> numbers_or(std::string_view key, std::span<const double> fallback, Range range) const;
  /// A required name: a non-empty string of letters, digits, '_' and '-' (it labels output rows).
  std::string word(std::string_view key) const;
  /// An optional array of distinct strings, each one of `allowed`; `fallback` when the key is absent.
  /// A non-array value, a non-string element, a name not in `allowed` or a repeated name is an error
  /// naming the file, the key and the allowed names. An empty array is allowed.
  std::vector<std::string> choices_or(std::string_view key, std::span<const std::string_view> fallback,
                                      std::span<const std::string_view> allowed) const;
  /// Marks keys as known without reading them (for keys that belong to another consumer).
  void accept(std::initializer_list<std::string_view> keys) const;
  /// Throws for any key of the table that was neither read nor accepted, naming the nearest known
  /// key (nearest_key) where one is close.
  void reject_unknown_keys() const;
  /// Throws "is not a known key" for `key`, with the nearest of `known` where one is close.
  [[noreturn]] void fail_unknown(std::string_view key, std::span<const std::string_view> known) const;
  /// The keys of the table that were neither read nor accepted, in table order.
  std::vector<std::string> unread_keys() const;
  /// Throws a ParameterError about `key` with `what` as the reason.
  [[noreturn]] void fail(std::string_view key, std::string_view what) const;
  /// Throws a ParameterError "SOURCE: [table] key = value what".
  [[noreturn]] void fail_value(std::string_view key, std::string_view value, std::string_view what) const;

  const std::string& source() const { return source_; }
  const std::string& table_name() const { return table_name_; }
  /// Every key read so far with the value it was read as, defaults included: the table as the
  /// program understood it, which reads back to the same values (results record it).
  const toml::table& resolved() const { return resolved_; }

 private:
  const toml::node* find(std::string_view key) const;
  std::string where(std::string_view key) const;

  template <class Value>
  void record(std::string_view key, Value&& value) const {
    resolved_.insert_or_assign(key, std::forward<Value>(value));
  }

  const toml::table& table_;
  std::string source_;
  std::string table_name_;
  mutable std::set<std::string, std::less<>> used_;
  mutable toml::table resolved_;
};

/// Whether a result lists an optional key always or only when it is set off its default: an option
/// that is off unless asked for (a cut-off, a relaxation time) is absent from the record of a
/// material that does not use it.
enum class Listed { Always, WhenSet };

/// A model's parameters are listed once, in `Params::fields(io)`: each field with its key, its
/// allowed range and (for optional keys) its default, the field's initial value in the struct, in the
/// order results list them. Four visitors walk that list: FieldReader fills the fields from a TOML
/// table (Params::read), FieldChecker checks a struct built in code against the same ranges (the
/// model's constructor), FieldDescriber writes each field as the TOML that reads it back (the record
/// of a result), and KeyLister collects the keys (what a `[material]` table may hold). So reader,
/// checker and describer share one set of keys, ranges and defaults.
///
/// `io.when(applies)` marks keys that apply only under a condition on other fields (one kind of
/// elasticity's): the reader, checker and describer skip them when it is false; the lister lists them.
template <class Io>
class OnlyWhen {
 public:
  OnlyWhen(const Io& io, bool applies) : io_(io), applies_(applies) {}
  template <class... Args>
  void number(Args&&... args) const {
    if (applies_) io_.number(std::forward<Args>(args)...);
  }
  template <class... Args>
  void number_or(Args&&... args) const {
    if (applies_) io_.number_or(std::forward<Args>(args)...);
  }

 private:
  const Io& io_;
  bool applies_;
};

class FieldReader {
 public:
  explicit FieldReader(const TableReader& table) : table_(table) {}
  OnlyWhen<FieldReader> when(bool applies) const { return {*this, applies}; }
  /// A required key.
  void number(std::string_view key, double& field, Range range, std::string_view unit = "") const {
    field = table_.number(key, range, unit);
  }
  /// An optional key whose default is the field's current (initial) value.
  void number_or(std::string_view key, double& field, Range range, std::string_view unit = "",
                 Listed = Listed::Always) const {
    field = table_.number_or(key, field, range, unit);
  }
  /// An optional key without a default value: absent, the field keeps +∞ ("none"); listed when given.
  void number_if_given(std::string_view key, double& field, Range range, std::string_view unit = "") const {
    if (table_.has(key))
      field = table_.number(key, range, unit);
    else
      table_.accept({key});
  }
  /// An optional key naming one of the values of `table`; the field's current value is the default.
  template <class Enum, std::size_t N>
  void choice_or(std::string_view key, Enum& field, const EnumTable<Enum, N>& table,
                 Listed = Listed::Always) const {
    field = *parse_name(table, table_.choice_or(key, name_of(table, field), names_of(table)));
  }
  /// An optional string of `length` characters; the field's current value is the default.
  void text_or(std::string_view key, std::string& field, Length length) const {
    field = table_.text_or(key, field, length);
  }
  /// A required path of an existing file, relative to the table's file; the field holds it absolute.
  void file(std::string_view key, std::string& field) const { field = table_.file(key); }
  /// An optional integer in [lo, hi]; the field's current value is the default.
  void integer_or(std::string_view key, int& field, int lo, int hi) const {
    field = static_cast<int>(table_.integer_or(key, field, lo, hi));
  }
  /// An optional array of numbers, each in `range`, as many as `count` allows; the field's current
  /// value is the default.
  void numbers_or(std::string_view key, std::vector<double>& field, Range range, Count count = Count::any(),
                  Listed = Listed::Always) const;
  /// An optional true or false; the field's current value is the default.
  void boolean_or(std::string_view key, bool& field) const { field = table_.boolean_or(key, field); }

 private:
  const TableReader& table_;
};

/// Checks fields set in code: a value outside its range throws ParameterError
/// "OWNER: key = value is out of range (allowed: ...)", as TableReader says it of a file's key.
class FieldChecker {
 public:
  explicit FieldChecker(std::string_view owner) : owner_(owner) {}
  OnlyWhen<FieldChecker> when(bool applies) const { return {*this, applies}; }
  void number(std::string_view key, const double& field, Range range, std::string_view unit = "") const;
  void number_or(std::string_view key, const double& field, Range range, std::string_view unit = "",
                 Listed = Listed::Always) const {
    number(key, field, range, unit);
  }
  void number_if_given(std::string_view key, const double& field, Range range,
                       std::string_view unit = "") const {
    if (field != std::numeric_limits<double>::infinity()) number(key, field, range, unit);
  }
  /// An enum value is always one of its names.
  template <class Enum, std::size_t N>
  void choice_or(std::string_view, const Enum&, const EnumTable<Enum, N>&, Listed = Listed::Always) const {}
  void text_or(std::string_view key, const std::string& field, Length length) const;
  /// The path must name an existing file (a struct built in code holds it as the file system reads it).
  void file(std::string_view key, const std::string& field) const;
  void integer_or(std::string_view key, const int& field, int lo, int hi) const;
  void numbers_or(std::string_view key, const std::vector<double>& field, Range range,
                  Count count = Count::any(), Listed = Listed::Always) const;
  /// A bool is always true or false.
  void boolean_or(std::string_view, const bool&) const {}

 private:
  [[noreturn]] void fail(std::string_view key, std::string_view value, std::string_view what) const;

  std::string_view owner_;
};

/// (key, value) pairs: a material as the TOML text that reads it back.
using KeyValues = std::vector<std::pair<std::string, std::string>>;

/// Appends each field to a list of (key, value) as TOML reads it back: numbers as exact_number(),
/// names quoted. A Listed::WhenSet key is left out at the value it has
/// in `defaults` (the list of a default-constructed struct; nullptr: every key is listed).
class FieldDescriber {
 public:
  FieldDescriber(KeyValues& out, const KeyValues* defaults) : out_(out), defaults_(defaults) {}
  OnlyWhen<FieldDescriber> when(bool applies) const { return {*this, applies}; }
  void number(std::string_view key, const double& field, Range, std::string_view = "") const {
    add(key, exact_number(field), Listed::Always);
  }
  void number_or(std::string_view key, const double& field, Range, std::string_view = "",
                 Listed listed = Listed::Always) const {
    add(key, exact_number(field), listed);
  }
  void number_if_given(std::string_view key, const double& field, Range, std::string_view = "") const {
    if (field != std::numeric_limits<double>::infinity()) add(key, exact_number(field), Listed::Always);
  }
  template <class Enum, std::size_t N>
  void choice_or(std::string_view key, const Enum& field, const EnumTable<Enum, N>& table,
                 Listed listed = Listed::Always) const {
    add(key, quoted(name_of(table, field)), listed);
  }
  void text_or(std::string_view key, const std::string& field, Length) const {
    add(key, quoted(field), Listed::Always);
  }
  void file(std::string_view key, const std::string& field) const { add(key, quoted(field), Listed::Always); }
  void integer_or(std::string_view key, const int& field, int, int) const {
    add(key, std::to_string(field), Listed::Always);
  }
  /// As a TOML array: [1, 0.5].
  void numbers_or(std::string_view key, const std::vector<double>& field, Range, Count = Count::any(),
                  Listed listed = Listed::Always) const;
  void boolean_or(std::string_view key, const bool& field) const {
    add(key, field ? "true" : "false", Listed::Always);
  }

 private:
  static std::string quoted(std::string_view text) {
    std::string out(1, '"');  // appended, not `"\"" + ...`: GCC 12 warns falsely of that (-Wrestrict)
    return out.append(text).append(1, '"');
  }
  void add(std::string_view key, std::string value, Listed listed) const;

  KeyValues& out_;
  const KeyValues* defaults_;
};

/// Collects the keys of a fields() list, those under a condition included.
class KeyLister {
 public:
  explicit KeyLister(std::vector<std::string_view>& keys) : keys_(keys) {}
  const KeyLister& when(bool) const { return *this; }
  template <class... Rest>
  void number(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void number_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void number_if_given(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void choice_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void text_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void file(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void integer_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void numbers_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }
  template <class... Rest>
  void boolean_or(std::string_view key, const Rest&...) const {
    keys_.push_back(key);
  }

 private:
  std::vector<std::string_view>& keys_;
};

/// A Params struct read from `table` through its fields() list (the struct's initial values are the
/// defaults of optional keys), starting from `params`.
template <class Params>
Params read_fields(const TableReader& table, Params params = {}) {
  params.fields(FieldReader(table));
  return params;
}

/// `params` after checking every field against its range (Params::fields with a FieldChecker);
/// `owner` names the model in the message. For constructors: `params_(validated(params, kName))`.
template <class Params>
const Params& validated(const Params& params, std::string_view owner) {
  Params copy = params;
  copy.fields(FieldChecker(owner));
  return params;
}

/// `params` as (key, value) pairs in the order of its fields() list, as TOML that reads it back.
template <class Params>
KeyValues described_fields(const Params& params) {
  KeyValues defaults, out;
  Params{}.fields(FieldDescriber(defaults, nullptr));
  Params copy = params;
  copy.fields(FieldDescriber(out, &defaults));
  return out;
}

/// The keys of a Params struct's fields() list, in its order.
template <class Params>
std::vector<std::string_view> field_keys() {
  std::vector<std::string_view> keys;
  Params{}.fields(KeyLister(keys));
  return keys;
}

/// The one of `known` nearest to `key` by edit distance (insertions, deletions, substitutions and
/// swaps of neighbours), if it is close: at most 2 edits and at most a third of the key's length
/// (so "fricton_angle" finds "friction_angle", while "xyz" finds nothing).
std::optional<std::string_view> nearest_key(std::string_view key, std::span<const std::string_view> known);

/// Parses a TOML file, turning syntax errors into ParameterError with file, line and column.
toml::table parse_toml_file(const std::string& path);

/// The source that apply_override gives the values it sets: "--set " followed by the assignment.
inline constexpr std::string_view kOverridePrefix = "--set ";

/// Applies one `section.key=value` override (the `--set` option) to `root`. The value is parsed
/// as a TOML value (number, boolean, quoted or bare string, array); the key must name an existing
/// table. A value starting with `[` or `{` that is not valid TOML is an error (not a bare string).
/// The value's source is "--set section.key=value", so TableReader's messages about it name the
/// option, not the file.
void apply_override(toml::table& root, std::string_view assignment);

/// " [with --set a=1, b=2]" for the overrides applied, or "" without any: appended to a refusal
/// that names a file's key, since one of the options may be what made it wrong (a model switched
/// with --set leaves the file's keys short, a column height set with --set no longer fits the
/// file's spacing).
std::string overrides_note(std::span<const std::string> overrides);

/// read() (reading inputs that `overrides` changed); a ParameterError that does not already name
/// its --set option gets overrides_note appended.
template <class Read>
auto blaming_overrides(std::span<const std::string> overrides, Read&& read) {
  try {
    return read();
  } catch (const ParameterError& e) {
    const std::string what = e.what();
    if (overrides.empty() || what.starts_with(kOverridePrefix)) throw;
    throw ParameterError(what + overrides_note(overrides));
  }
}

}  // namespace soilsph
