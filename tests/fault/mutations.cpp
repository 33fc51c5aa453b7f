// The fuzz cases: mutants of the shipped TOML and CSV inputs and of the command line, each with what
// the harness knows about its right exit status. Mutations work on the text (so that a mutant can be
// anything a user can type, including what no TOML library would write) and the expectations are
// derived with toml++ from the mutant, following the documented rules of the readers (the ranges of
// docs and constitutive/, sph/scene.cpp, verification/paths/strain_path_csv.cpp), not their code.
#include <toml++/toml.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "tests/fault/fuzz.h"

namespace soilsph::fuzz {

namespace {

// ---------------------------------------------------------------------------------------------------
// Random numbers: SplitMix64, seeded from (seed, index) alone so that each case stands by itself.

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(next() % n); }
  bool chance(double p) { return static_cast<double>(next() >> 11) * 0x1.0p-53 < p; }
  template <class T>
  const T& pick(const std::vector<T>& v) {
    return v.at(below(v.size()));
  }

 private:
  std::uint64_t state_;
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::string format_double(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", x);
  std::string s = text;
  // A TOML float needs a '.' or an exponent.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("fuzz: cannot read " + path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---------------------------------------------------------------------------------------------------
// A TOML file as lines: table headers and `key = value` lines located, everything else kept as text.

struct Line {
  std::string text;
  std::string table;  ///< the table the line belongs to ("" before the first header)
  std::string key;    ///< a key line's key, else empty
  std::size_t value_begin = 0, value_end = 0;
  bool header = false;
};

struct Doc {
  std::vector<Line> lines;
};

Doc parse_doc(const std::string& text) {
  Doc doc;
  std::string table;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    Line line;
    line.text = text.substr(start, end - start);
    start = end + 1;
    const std::string t = trim(line.text);
    if (t.starts_with('[')) {
      line.header = true;
      table = trim(t.substr(1, t.find(']') == std::string::npos ? std::string::npos : t.find(']') - 1));
    } else if (!t.empty() && t.front() != '#') {
      const std::size_t eq = line.text.find('=');
      if (eq != std::string::npos) {
        line.key = trim(line.text.substr(0, eq));
        std::size_t b = line.text.find_first_not_of(" \t", eq + 1);
        if (b == std::string::npos) b = line.text.size();
        // The value ends at a comment outside quotes, trailing spaces dropped.
        bool quoted = false;
        std::size_t e = line.text.size();
        for (std::size_t k = b; k < line.text.size(); ++k) {
          if (line.text[k] == '"') quoted = !quoted;
          if (line.text[k] == '#' && !quoted) {
            e = k;
            break;
          }
        }
        while (e > b && (line.text[e - 1] == ' ' || line.text[e - 1] == '\t')) --e;
        line.value_begin = b;
        line.value_end = e;
      }
    }
    line.table = table;
    doc.lines.push_back(line);
  }
  return doc;
}

Line text_line(std::string text) {
  Line line;
  line.text = std::move(text);
  return line;
}

std::string render(const Doc& doc) {
  std::string out;
  for (const Line& line : doc.lines) out += line.text + '\n';
  return out;
}

std::vector<std::size_t> key_lines(const Doc& doc) {
  std::vector<std::size_t> k;
  for (std::size_t i = 0; i < doc.lines.size(); ++i)
    if (!doc.lines[i].key.empty()) k.push_back(i);
  return k;
}

std::vector<std::string> tables_of(const Doc& doc) {
  std::vector<std::string> t;
  for (const Line& line : doc.lines)
    if (line.header) t.push_back(line.table);
  return t;
}

std::string value_text(const Line& line) {
  return line.text.substr(line.value_begin, line.value_end - line.value_begin);
}

void set_value(Line& line, const std::string& value) {
  line.text = line.text.substr(0, line.value_begin) + value + line.text.substr(line.value_end);
  line.value_end = line.value_begin + value.size();
}

// ---------------------------------------------------------------------------------------------------
// The documented keys: type, required or not, admissible range (some depend on other keys), values
// at and around the edges, and the keys whose message may rightly name a change of this one.

enum class Type { Number, Integer, Boolean, String, Names };

struct Interval {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  bool lo_open = true, hi_open = true;
  bool or_zero = false;  ///< 0 ("off") is admissible too
  bool contains(double x) const {
    if (!std::isfinite(x)) return false;
    if (or_zero && x == 0.0) return true;
    return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A number of the parsed document, or `fallback`.
double number_at(const toml::table& doc, std::string_view table, std::string_view key, double fallback) {
  const toml::node* t = doc.get(table);
  if (!t || !t->is_table()) return fallback;
  const toml::node* n = t->as_table()->get(key);
  if (!n || n->is_boolean()) return fallback;
  return n->value<double>().value_or(fallback);
}
std::string string_at(const toml::table& doc, std::string_view table, std::string_view key,
                      const std::string& fallback) {
  const toml::node* t = doc.get(table);
  if (!t || !t->is_table()) return fallback;
  const toml::node* n = t->as_table()->get(key);
  if (!n) return fallback;
  return n->value_exact<std::string>().value_or(fallback);
}

struct Spec {
  std::string table, key;
  Type type;
  bool required;
  std::vector<std::string> edges;       ///< TOML values at and around the admissible range's edges
  std::vector<std::string> dependents;  ///< keys a message may name instead when this key changes
  std::vector<std::string> allowed;     ///< String and Names: the admissible names
  /// Number: the admissible interval given the rest of the document.
  std::function<Interval(const toml::table&)> interval = [](const toml::table&) { return Interval{}; };
  /// Integer: the admissible closed range given the rest of the document.
  std::function<std::pair<long long, long long>(const toml::table&)> integer_range = [](const toml::table&) {
    return std::pair<long long, long long>(std::numeric_limits<long long>::min(),
                                           std::numeric_limits<long long>::max());
  };
  /// Number: a vector [x, y] of finite components and magnitude ≤ vector_magnitude is admissible
  /// too (gravity's direction); 0: numbers only.
  double vector_magnitude = 0.0;
};

Interval open(double lo, double hi) {
  return {lo, hi, true, true};
}
Interval closed(double lo, double hi) {
  return {lo, hi, false, false};
}
Interval closed_open(double lo, double hi) {
  return {lo, hi, false, true};
}
Interval open_closed(double lo, double hi) {
  return {lo, hi, true, false};
}
std::function<Interval(const toml::table&)> fixed(Interval i) {
  return [i](const toml::table&) { return i; };
}

const std::vector<std::string> kMaterialKeyNames = {"model",           "density",
                                                    "young_modulus",   "poisson_ratio",
                                                    "friction_angle",  "cohesion",
                                                    "dilatancy_angle", "compression_index",
                                                    "swelling_index",  "initial_void_ratio",
                                                    "elasticity",      "elastic_pressure_floor",
                                                    "integrator",      "substep_tolerance",
                                                    "implicit_alpha",  "plastic_potential",
                                                    "implicit_tolerance"};

std::vector<Spec> make_specs() {
  const auto positive = fixed(open(0, kInf));
  const auto non_negative = fixed(closed_open(0, kInf));
  std::vector<std::string> all_material = kMaterialKeyNames;
  all_material.push_back("lateral_stress_ratio");
  std::vector<Spec> s;
  // [material] (constitutive/models/*.cpp, docs: the same ranges)
  s.push_back({"material",
               "model",
               Type::String,
               true,
               {"\"linear-elastic\"", "\"drucker-prager\"", "\"modified-cam-clay\"", "\"Drucker-Prager\"",
                "\"cam-clay\"", "\"\"", "\"drucker-prager \""},
               all_material,
               {"linear-elastic", "drucker-prager", "modified-cam-clay"}});
  s.push_back({"material",
               "density",
               Type::Number,
               true,
               {"0", "-0.0", "-2000.0", "1e-300", "5e-324"},
               {},
               {},
               positive});
  s.push_back({"material",
               "young_modulus",
               Type::Number,
               true,
               {"0", "-1.0e6", "1.0", "0.9999999", "1e-300", "5e-324", "1e12", "1e24", "1e25", "1e40"},
               {},
               {},
               fixed(closed(1.0, 1e12))});
  s.push_back({"material",
               "poisson_ratio",
               Type::Number,
               true,
               {"0.5", "-1.0", "0.4999999", "-0.9999999", "0.5000001", "-1.0000001", "0.0", "0.49"},
               {"lateral_stress_ratio"},
               {},
               fixed(open(-1, 0.5))});
  s.push_back({"material",
               "friction_angle",
               Type::Number,
               true,
               {"0.0", "90.0", "89.9999", "1e-9", "-1e-9", "90.0000001", "25.0", "30.0", "1.0", "0.9999999"},
               {"dilatancy_angle", "lateral_stress_ratio"},
               {},
               [](const toml::table& d) {  // MCC: M vanishes below 1 degree (docs/reference/materials.md)
                 return string_at(d, "material", "model", "") == "modified-cam-clay" ? closed_open(1, 90)
                                                                                    : open(0, 90);
               }});
  s.push_back(
      {"material", "cohesion", Type::Number, false, {"-1e-9", "1e308", "1e6", "0"}, {}, {}, non_negative});
  s.push_back(
      {"material",
       "dilatancy_angle",
       Type::Number,
       false,
       {"35.0", "35.0000001", "-1e-9", "20.0"},
       {},
       {},
       [](const toml::table& d) { return closed(0, number_at(d, "material", "friction_angle", 90)); }});
  s.push_back({"material",
               "plastic_potential",
               Type::String,
               false,
               {"\"matched\"", "\"paper-eq20\"", "\"paper\"", "\"Matched\"", "\"\""},
               {},
               {"matched", "paper-eq20"}});
  s.push_back({"material",
               "compression_index",
               Type::Number,
               true,
               {"0.019", "0.0190001", "0", "1e308"},
               {"swelling_index"},
               {},
               positive});
  s.push_back(
      {"material",
       "swelling_index",
       Type::Number,
       true,
       {"0.085", "0.0849999", "0", "1e-300"},
       {},
       {},
       [](const toml::table& d) { return open(0, number_at(d, "material", "compression_index", kInf)); }});
  s.push_back({"material",
               "initial_void_ratio",
               Type::Number,
               true,
               {"0", "-0.1", "1e308", "1e-300"},
               {},
               {},
               positive});
  s.push_back({"material",
               "elasticity",
               Type::String,
               false,
               {"\"constant\"", "\"pressure-dependent\"", "\"linear\""},
               {"young_modulus", "elastic_pressure_floor"},
               {"constant", "pressure-dependent"}});
  s.push_back({"material",
               "elastic_pressure_floor",
               Type::Number,
               false,
               {"0", "-1", "1e-300", "1e308"},
               {},
               {},
               positive});
  s.push_back({"material",
               "integrator",
               Type::String,
               false,
               {"\"explicit\"", "\"substep\"", "\"implicit\"", "\"cvode\"", "\"Explicit\""},
               {},
               {"explicit", "substep", "implicit"}});
  s.push_back({"material",
               "substep_tolerance",
               Type::Number,
               false,
               {"1e-12", "9.9e-13", "0.01", "0.0100001", "0"},
               {},
               {},
               fixed(closed(1e-12, 1e-2))});
  s.push_back({"material",
               "implicit_alpha",
               Type::Number,
               false,
               {"0.5", "0.4999999", "1.0", "1.0000001"},
               {},
               {},
               fixed(closed(0.5, 1.0))});
  s.push_back({"material",
               "implicit_tolerance",
               Type::Number,
               false,
               {"0", "-1e-300", "1e-30", "9.9e-13", "1e-12", "1e-3", "0.01", "0.0100001"},
               {},
               {},
               fixed(Interval{1e-12, 1e-2, false, false, true})});
  // [scene] (sph/scene.cpp, docs/method/sph.md)
  s.push_back({"scene",
               "column_width",
               Type::Number,
               true,
               {"0.016", "0.0161", "0", "1e308", "1e3", "1e-300"},
               {"particle_spacing", "floor_length"},
               {},
               positive});
  s.push_back({"scene",
               "column_height",
               Type::Number,
               true,
               {"0.016", "0.0161", "0", "1e308", "100.0"},
               {"particle_spacing"},
               {},
               positive});
  s.push_back({"scene",
               "particle_spacing",
               Type::Number,
               true,
               {"0.01", "0.00999", "0", "1e-6", "1e-5", "0.001"},
               {},
               {},
               [](const toml::table& d) {
                 return open(0, std::min(number_at(d, "scene", "column_width", kInf),
                                         number_at(d, "scene", "column_height", kInf)) /
                                    4);
               }});
  s.push_back({"scene",
               "smoothing_ratio",
               Type::Number,
               true,
               {"1.0", "2.0", "0.9999999", "2.0000001"},
               {"boundary_layers"},
               {},
               fixed(closed(1, 2))});
  s.push_back({"scene",
               "end_time",
               Type::Number,
               true,
               {"0", "1e9", "1e15", "0.01", "0.0099", "5e-324"},
               {"frame_interval"},
               {},
               positive});
  {
    Spec gravity{"scene", "gravity", Type::Number, true, {"-1e-9", "0", "1e4", "1e308", "1e30", "[1e4, 1.0]"},
                 {},      {},        non_negative};
    gravity.vector_magnitude = 1e4;  // docs/reference/scenes.md: g, or [gx, gy] pointing anywhere
    s.push_back(gravity);
  }
  s.push_back({"scene",
               "wall_withdrawal",
               Type::String,
               true,
               {"\"none\"", "\"instant\"", "\"slow\""},
               {},
               {"instant", "none"}});
  {
    Spec b{"scene", "boundary_layers", Type::Integer, false, {"2", "3", "10", "11", "0", "-1", "3.0"}, {},
           {}};
    b.integer_range = [](const toml::table& d) {
      const double ratio = number_at(d, "scene", "smoothing_ratio", 1.3);
      return std::pair<long long, long long>(static_cast<long long>(std::ceil(2.0 * ratio - 1e-9)), 10);
    };
    s.push_back(b);
  }
  s.push_back({"scene",
               "floor_length",
               Type::Number,
               false,
               {"0.04", "0.0400001", "1000.0", "999.9", "1e308"},
               {},
               {},
               [](const toml::table& d) { return open(number_at(d, "scene", "column_width", 0), 1e3); }});
  s.push_back({"scene", "stop_at_rest", Type::Boolean, false, {"true", "false", "\"true\"", "1"}, {}, {}});
  s.push_back({"scene", "max_run_hours", Type::Number, false, {"0", "1e-300", "1e308", "-1"}, {}, {}, positive});
  s.push_back({"scene", "rest_speed", Type::Number, false, {"0", "1e-300", "1e308"}, {}, {}, positive});
  s.push_back({"scene", "rest_duration", Type::Number, false, {"0", "1e-300", "1e308"}, {}, {}, positive});
  s.push_back({"scene",
               "rest_fraction",
               Type::Number,
               false,
               {"0.5", "0.5000001", "1.0", "1.0000001"},
               {},
               {},
               fixed(open_closed(0.5, 1.0))});
  // [initial]
  s.push_back({"initial",
               "lateral_stress_ratio",
               Type::Number,
               false,
               {"0", "1", "1e-300", "0.9999999", "0.1"},
               {},
               {},
               fixed(open(0, 1))});
  s.push_back({"initial",
               "overconsolidation_ratio",
               Type::Number,
               false,
               {"0.9999999", "1.0", "1000.0", "999.999"},
               {},
               {},
               fixed(closed_open(1, 1e3))});
  s.push_back(
      {"initial", "preconsolidation_floor", Type::Number, false, {"0", "1e-300", "1e308", "1e12"}, {}, {}, fixed(open_closed(0, 1e12))});
  // [numerics]
  s.push_back({"numerics",
               "artificial_viscosity_alpha",
               Type::Number,
               false,
               {"-1e-9", "0", "1e6", "1e308"},
               {},
               {},
               non_negative});
  s.push_back({"numerics",
               "artificial_viscosity_beta",
               Type::Number,
               false,
               {"-1e-9", "0", "1e6", "1e308"},
               {},
               {},
               non_negative});
  s.push_back(
      {"numerics", "artificial_stress", Type::Boolean, false, {"true", "false", "\"yes\"", "0"}, {}, {}});
  s.push_back({"numerics",
               "artificial_stress_epsilon",
               Type::Number,
               false,
               {"-1e-9", "1.0000001", "0", "1"},
               {},
               {},
               fixed(closed(0, 1))});
  s.push_back({"numerics",
               "artificial_stress_exponent",
               Type::Number,
               false,
               {"0", "1e3", "1e-300"},
               {},
               {},
               positive});
  s.push_back({"numerics",
               "cfl",
               Type::Number,
               false,
               {"0", "2.0", "2.0000001", "1e-300", "1.7", "0.99"},
               {"density_diffusion"},
               {},
               fixed(open_closed(0, 2))});
  s.push_back({"numerics",
               "velocity_gradient_correction",
               Type::Boolean,
               false,
               {"true", "false", "\"no\""},
               {},
               {}});
  s.push_back({"numerics",
               "density_diffusion",
               Type::Number,
               false,
               {"0", "0.1", "0.25", "0.2500001", "-0.1", "1.5", "\"0.1\""},
               {"cfl"},
               {},
               [](const toml::table& d) {  // δ × cfl ≤ 0.25 (sph/scene_settings.h), cfl's default 0.5
                 return closed(0, std::min(1.0, 0.25 / number_at(d, "numerics", "cfl", 0.5)));
               }});
  s.push_back({"numerics",
               "ghost_body_force",
               Type::Boolean,
               false,
               {"true", "false", "\"no\""},
               {},
               {}});
  s.push_back({"numerics",
               "kernel",
               Type::String,
               false,
               {"\"cubic-spline\"", "\"wendland-c2\"", "\"Wendland-C2\"", "\"quintic\"", "\"\""},
               {},
               {"cubic-spline", "wendland-c2"}});
  // [output]
  s.push_back(
      {"output",
       "frame_interval",
       Type::Number,
       false,
       {"0.02", "0.0200001", "5e-324", "1e-9", "0"},
       {},
       {},
       [](const toml::table& d) { return open(0, number_at(d, "scene", "end_time", kInf) * (1 + 1e-9)); }});
  s.push_back({"output", "layer_thickness", Type::Number, false, {"0", "1e-300", "1e300"}, {}, {}, positive});
  s.push_back({"output",
               "fields",
               Type::Names,
               false,
               {"[]", "[\"p\", \"p\"]", "[\"bogus\"]", "[1]", "\"p\"", "[\"p\", \"q\"]"},
               {},
               {"velocity", "speed", "stress", "p", "q", "plastic_strain", "density", "layer", "material"}});
  return s;
}

const std::vector<Spec>& specs() {
  static const std::vector<Spec> s = make_specs();
  return s;
}

const Spec* find_spec(const std::string& table, const std::string& key) {
  for (const Spec& s : specs())
    if (s.table == table && s.key == key) return &s;
  return nullptr;
}

/// Whether the document's model reads `key` of [material] (other models' keys are only noted).
bool material_key_used(const toml::table& doc, const std::string& key) {
  const std::string model = string_at(doc, "material", "model", "");
  const std::string elasticity = string_at(doc, "material", "elasticity", "pressure-dependent");
  const bool dp = model == "drucker-prager", mcc = model == "modified-cam-clay",
             le = model == "linear-elastic";
  if (key == "model" || key == "density" || key == "poisson_ratio") return true;
  if (key == "young_modulus") return dp || le || (mcc && elasticity == "constant");
  if (key == "friction_angle") return dp || mcc;
  if (key == "cohesion" || key == "dilatancy_angle" || key == "plastic_potential") return dp;
  if (key == "compression_index" || key == "swelling_index" || key == "initial_void_ratio" ||
      key == "elasticity" || key == "implicit_alpha" || key == "implicit_tolerance")
    return mcc;
  if (key == "elastic_pressure_floor") return mcc && elasticity == "pressure-dependent";
  if (key == "integrator" || key == "substep_tolerance") return dp || mcc;
  return false;
}

/// The exit status a value of `spec` calls for, judged as the documented reader would (a TOML value
/// of the wrong type, outside the range or not among the names is an input error).
Expect judge(const Spec& spec, const toml::node& node, const toml::table& doc) {
  switch (spec.type) {
    case Type::Number: {
      if (const toml::array* a = node.as_array(); a && spec.vector_magnitude > 0.0) {
        const std::optional<double> x = a->size() == 2 ? (*a)[0].value<double>() : std::nullopt;
        const std::optional<double> y = a->size() == 2 ? (*a)[1].value<double>() : std::nullopt;
        if (!x || !y || (*a)[0].is_boolean() || (*a)[1].is_boolean()) return Expect::InputError;
        const double magnitude = std::hypot(*x, *y);
        return std::isfinite(magnitude) && magnitude <= spec.vector_magnitude ? Expect::Any : Expect::InputError;
      }
      const std::optional<double> v = node.value<double>();
      if (!v || node.is_boolean()) return Expect::InputError;
      return spec.interval(doc).contains(*v) ? Expect::Any : Expect::InputError;
    }
    case Type::Integer: {
      const std::optional<long long> v = node.value_exact<long long>();
      if (!v) return Expect::InputError;
      const auto [lo, hi] = spec.integer_range(doc);
      return *v >= lo && *v <= hi ? Expect::Any : Expect::InputError;
    }
    case Type::Boolean:
      return node.value_exact<bool>() ? Expect::Any : Expect::InputError;
    case Type::String: {
      const std::optional<std::string> v = node.value_exact<std::string>();
      if (!v) return Expect::InputError;
      return std::find(spec.allowed.begin(), spec.allowed.end(), *v) != spec.allowed.end()
                 ? Expect::Any
                 : Expect::InputError;
    }
    case Type::Names: {
      const toml::array* a = node.as_array();
      if (!a) return Expect::InputError;
      std::vector<std::string> seen;
      for (const toml::node& e : *a) {
        const std::optional<std::string> v = e.value_exact<std::string>();
        if (!v || std::find(spec.allowed.begin(), spec.allowed.end(), *v) == spec.allowed.end() ||
            std::find(seen.begin(), seen.end(), *v) != seen.end())
          return Expect::InputError;
        seen.push_back(*v);
      }
      return Expect::Any;
    }
  }
  return Expect::Any;
}

std::optional<toml::table> try_parse(const std::string& text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

// ---------------------------------------------------------------------------------------------------
// Value pools.

const std::vector<std::string> kTypeValues = {"\"text\"", "\"\"",       "\"1.0e6\"", "true",
                                              "false",    "[1.0, 2.0]", "[]",        "{ a = 1 }",
                                              "{}",       "1979-05-27", "07:32:00",  "1979-05-27T07:32:00Z"};
const std::vector<std::string> kSpecialValues = {"nan", "+nan", "-nan", "inf", "+inf", "-inf"};
const std::vector<std::string> kNumberValues = {"0",
                                                "0.0",
                                                "-0.0",
                                                "-1",
                                                "-1.0",
                                                "-1e6",
                                                "1e308",
                                                "1.7976931348623157e308",
                                                "-1e308",
                                                "1e30",
                                                "1e15",
                                                "5e-324",
                                                "1e-300",
                                                "1e-30",
                                                "9223372036854775807",
                                                "-9223372036854775808",
                                                "1",
                                                "2",
                                                "100"};
const std::vector<std::string> kBrokenValues = {"99999999999999999999",
                                                "1e",
                                                ".5",
                                                "1,5",
                                                "0x",
                                                "1__0",
                                                "\"unterminated",
                                                "[1, 2",
                                                "{ a = ",
                                                "",
                                                "nan0",
                                                "1e400",
                                                "1.0.0",
                                                "--1"};

/// A value in place of `old` for `spec` (or any key): another type, NaN, ±inf, zero, negative, huge,
/// tiny, just outside or inside the range, a scaled copy of the old number, or text TOML rejects.
std::string pick_value(Rng& rng, const Spec* spec, const std::string& old, std::string* how) {
  const double r = static_cast<double>(rng.below(1000)) / 1000.0;
  if (spec && !spec->edges.empty() && r < 0.35) {
    *how = "a value at the edge of its range";
    return rng.pick(spec->edges);
  }
  if (r < 0.5) {
    const std::optional<toml::table> t = try_parse("v = " + old);
    const std::optional<double> x = t ? (*t)["v"].value<double>() : std::nullopt;
    if (x && !(*t)["v"].is_boolean()) {
      static const std::vector<int> powers = {-300, -30, -12, -6, -3, 3, 6, 12, 30, 300};
      const int k = rng.pick(powers);
      double y = *x * std::pow(10.0, k);
      if (rng.chance(0.2)) y = -*x;
      if (!std::isfinite(y)) y = y > 0 ? 1e308 : -1e308;
      *how = "the number scaled";
      return format_double(y);
    }
  }
  const std::size_t pool = rng.below(10);
  if (pool < 3) {
    *how = "a value of another type";
    return rng.pick(kTypeValues);
  }
  if (pool < 5) {
    *how = "NaN or infinity";
    return rng.pick(kSpecialValues);
  }
  if (pool < 8) {
    *how = "zero, negative, huge or tiny";
    return rng.pick(kNumberValues);
  }
  *how = "text that is not a TOML value";
  return rng.pick(kBrokenValues);
}

std::string random_garbage(Rng& rng, std::size_t n) {
  std::string g;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t kind = rng.below(6);
    if (kind == 0)
      g += '\0';
    else if (kind == 1)
      g += static_cast<char>(0x80 + rng.below(0x80));  // a stray UTF-8 continuation or lead byte
    else if (kind == 2)
      g += "=[]{}\"'#,.\\\n"[rng.below(12)];
    else
      g += static_cast<char>(0x20 + rng.below(0x5f));
  }
  return g;
}

// ---------------------------------------------------------------------------------------------------
// TOML mutations. Each returns the expectation it implies on its own (used only when it is the one
// mutation of a case) and the words that a non-zero exit's message should hold.

struct TomlMutation {
  std::string words;
  Expect expect = Expect::Any;
  std::string why;
  std::vector<std::string> keys;  ///< the key(s) an input error should name (empty: no key check)
};

const std::vector<std::string> kUnknownKeys = {
    "unknown_key", "young_modulu", "frictionangle", "Density", "end-time", "gravity2", "x", "cohesion_"};

TomlMutation mutate_toml(Rng& rng, Doc& doc, const toml::table& parsed, bool scene_file,
                         std::string& text_out) {
  TomlMutation m;
  const std::vector<std::size_t> keys = key_lines(doc);
  const std::size_t op = rng.below(100);
  const std::string original = render(doc);
  if (op < 40 && !keys.empty()) {  // replace a value
    Line& line = doc.lines[keys[rng.below(keys.size())]];
    // Outside a scene only [material] is the scene's table (a programme's [initial] is its own).
    const Spec* spec = scene_file || line.table == "material" ? find_spec(line.table, line.key) : nullptr;
    std::string how;
    const std::string old = value_text(line);
    const std::string value = pick_value(rng, spec, old, &how);
    set_value(line, value);
    m.words = "[" + line.table + "] " + line.key + " = " + old + " replaced by " + value + " (" + how + ")";
    m.keys = {line.key};
    // A scene's named materials ([materials.NAME]) have [material]'s keys: a message may name the
    // keys this one bounds (compression_index bounds swelling_index), though the value is not judged.
    if (const Spec* named =
            scene_file && line.table.starts_with("materials.") ? find_spec("material", line.key) : nullptr)
      for (const std::string& d : named->dependents) m.keys.push_back(d);
    if (spec) {
      for (const std::string& d : spec->dependents) m.keys.push_back(d);
      const std::optional<toml::table> v = try_parse("v = " + value);
      const bool used = line.table != "material" || material_key_used(parsed, line.key);
      if (v && used) {
        m.expect = judge(*spec, *(*v).get("v"), parsed);
        if (m.expect == Expect::InputError) m.why = "the value is not admissible for " + line.key;
      }
    }
  } else if (op < 52) {  // add a documented key that the file does not have
    std::vector<const Spec*> absent;
    const std::vector<std::string> tables = tables_of(doc);
    for (const Spec& s : specs()) {
      if (std::find(tables.begin(), tables.end(), s.table) == tables.end()) continue;
      if (!scene_file && s.table != "material") continue;
      bool present = false;
      for (std::size_t k : keys)
        present = present || (doc.lines[k].table == s.table && doc.lines[k].key == s.key);
      if (!present) absent.push_back(&s);
    }
    if (absent.empty()) return mutate_toml(rng, doc, parsed, scene_file, text_out);
    const Spec& spec = *absent[rng.below(absent.size())];
    std::string how;
    const std::string value = pick_value(rng, &spec, "1.0", &how);
    // Insert right after the table's header.
    for (std::size_t i = 0; i < doc.lines.size(); ++i) {
      if (doc.lines[i].header && doc.lines[i].table == spec.table) {
        Line line;
        line.text = spec.key + " = ";
        line.table = spec.table;
        line.key = spec.key;
        line.value_begin = line.value_end = line.text.size();
        set_value(line, value);
        doc.lines.insert(doc.lines.begin() + static_cast<long>(i) + 1, line);
        break;
      }
    }
    m.words = "[" + spec.table + "] " + spec.key + " = " + value + " added (" + how + ")";
    m.keys = {spec.key};
    for (const std::string& d : spec.dependents) m.keys.push_back(d);
    const std::optional<toml::table> v = try_parse("v = " + value);
    const bool used = spec.table != "material" || material_key_used(parsed, spec.key);
    if (v && used) {
      m.expect = judge(spec, *(*v).get("v"), parsed);
      if (m.expect == Expect::InputError) m.why = "the value is not admissible for " + spec.key;
    }
  } else if (op < 60 && !keys.empty()) {  // delete a key
    const std::size_t i = keys[rng.below(keys.size())];
    const Line line = doc.lines[i];
    doc.lines.erase(doc.lines.begin() + static_cast<long>(i));
    m.words = "[" + line.table + "] " + line.key + " deleted";
    const Spec* spec = find_spec(line.table, line.key);
    const bool used = line.table != "material" || material_key_used(parsed, line.key);
    if (spec && spec->required && used) {
      m.expect = Expect::InputError;
      m.why = line.key + " is required";
      m.keys = {line.key};
    }
  } else if (op < 66 && !keys.empty()) {  // repeat a key
    const std::size_t i = keys[rng.below(keys.size())];
    Line copy = doc.lines[i];
    std::string how = "the same value";
    if (rng.chance(0.5)) {
      const Spec* spec = find_spec(copy.table, copy.key);
      set_value(copy, pick_value(rng, spec, value_text(copy), &how));
    }
    doc.lines.insert(doc.lines.begin() + static_cast<long>(i) + 1, copy);
    m.words = "[" + copy.table + "] " + copy.key + " repeated (" + trim(copy.text) + ", " + how + ")";
    m.expect = Expect::InputError;
    m.why = "a key defined twice is a TOML error";
  } else if (op < 72) {  // an unknown key in a table
    const std::vector<std::string> tables = tables_of(doc);
    if (tables.empty()) return mutate_toml(rng, doc, parsed, scene_file, text_out);
    const std::string table = rng.pick(tables);
    const std::string key = rng.pick(kUnknownKeys);
    for (std::size_t i = 0; i < doc.lines.size(); ++i) {
      if (doc.lines[i].header && doc.lines[i].table == table) {
        Line line;
        line.text = key + " = 1.0";
        line.table = table;
        line.key = key;
        // Right after the header or one line further, but never past the end (a header on the last line).
        const std::size_t at = std::min(i + 1 + rng.below(2), doc.lines.size());
        doc.lines.insert(doc.lines.begin() + static_cast<long>(at), line);
        break;
      }
    }
    m.words = "unknown key " + key + " = 1.0 added to [" + table + "]";
    m.expect = Expect::InputError;
    m.why = key + " is not a known key of [" + table + "]";
    m.keys = {key};
  } else if (op < 78) {  // tables: an unknown one, a repeated header, a deleted or renamed header
    const std::size_t which = rng.below(4);
    std::vector<std::size_t> headers;
    for (std::size_t i = 0; i < doc.lines.size(); ++i)
      if (doc.lines[i].header) headers.push_back(i);
    if (which == 0 || headers.empty()) {
      const std::string name =
          rng.pick(std::vector<std::string>{"extra", "Material", "materials", "scene.sub"});
      doc.lines.push_back(text_line("[" + name + "]"));
      doc.lines.push_back(text_line("value = 1"));
      m.words = "unknown table [" + name + "] with value = 1 added";
      // A material file may be a scene file (point accepts one): other tables are ignored there.
      if (scene_file) {
        m.expect = Expect::InputError;
        m.why = "[" + name + "] is not a table of a scene";
        m.keys = {name.substr(0, name.find('.'))};
      }
    } else {
      const std::size_t h = headers[rng.below(headers.size())];
      const std::string table = doc.lines[h].table;
      bool has_keys = false;
      for (std::size_t k : keys) has_keys = has_keys || doc.lines[k].table == table;
      if (which == 1) {
        doc.lines.push_back(doc.lines[h]);
        doc.lines.push_back(text_line("density = 1.0"));
        m.words = "table [" + table + "] opened a second time (with density = 1.0)";
        m.expect = Expect::InputError;
        m.why = "a table defined twice is a TOML error";
      } else if (which == 2) {
        doc.lines.erase(doc.lines.begin() + static_cast<long>(h));
        m.words = "header [" + table + "] deleted (its keys join the table before)";
        if (has_keys) {
          m.expect = Expect::InputError;
          m.why = "the keys of [" + table + "] now sit in another table or at the top";
        }
      } else {
        const std::string name = table + "s";
        doc.lines[h].text = "[" + name + "]";
        m.words = "header [" + table + "] renamed [" + name + "]";
        if (scene_file || table == "material") {
          m.expect = Expect::InputError;
          m.why = "[" + name + "] is not a known table, or [material] is missing";
        }
      }
    }
  } else if (op < 84) {  // truncate
    const std::size_t cut = rng.below(original.size());
    text_out = original.substr(0, cut);
    m.words =
        "file truncated to " + std::to_string(cut) + " of " + std::to_string(original.size()) + " bytes";
    return m;
  } else if (op < 88) {  // empty or nothing but blanks and comments
    const std::size_t which = rng.below(3);
    text_out = which == 0 ? "" : which == 1 ? "\n  \n\t\n" : "# nothing but a comment\n";
    m.words = which == 0 ? "empty file" : which == 1 ? "file of blank lines" : "file of one comment";
    m.expect = Expect::InputError;
    m.why = "no [material] (or [scene]) table";
    return m;
  } else {  // garbage bytes
    text_out = original;
    const std::size_t which = rng.below(5);
    if (which == 0) {
      const std::size_t at = rng.below(text_out.size() + 1), n = 1 + rng.below(16);
      text_out.insert(at, random_garbage(rng, n));
      m.words = std::to_string(n) + " garbage bytes inserted at byte " + std::to_string(at);
    } else if (which == 1) {
      const std::size_t n = 1 + rng.below(8);
      for (std::size_t k = 0; k < n && !text_out.empty(); ++k)
        text_out[rng.below(text_out.size())] = random_garbage(rng, 1)[0];
      m.words = std::to_string(n) + " bytes overwritten with garbage";
    } else if (which == 2) {
      text_out = random_garbage(rng, 64 + rng.below(512));
      m.words = "file replaced by garbage bytes";
    } else if (which == 3) {
      text_out.insert(rng.below(text_out.size() + 1), std::string(100000, 'x'));
      m.words = "a run of 100000 'x' inserted";
    } else {
      for (char& c : text_out)
        if (c == '\n') c = '\r';
      m.words = "line ends changed to bare CR";
    }
    return m;
  }
  text_out = render(doc);
  return m;
}

// ---------------------------------------------------------------------------------------------------
// CSV mutations of the strain path (header d_xx,d_yy,d_zz,d_xy,d_yz,d_xz, then six finite numbers a
// row; blank lines and # comments skipped).

struct CsvMutation {
  std::string words;
  Expect expect = Expect::Any;
  std::string why;
  int line = 0;  ///< 1-based line an input error should name (0: none)
};

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}
std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + '\n';
  return out;
}
bool is_data_row(const std::string& line) {
  const std::string t = trim(line);
  return !t.empty() && t.front() != '#' && !t.starts_with("d_xx");
}
std::vector<std::string> split_cells(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream s(row);
  for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
  if (!row.empty() && row.back() == ',') cells.push_back("");
  return cells;
}
std::string join_cells(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t k = 0; k < cells.size(); ++k) out += (k ? "," : "") + cells[k];
  return out;
}

const std::vector<std::string> kBadCells = {"nan", "NaN",   "inf",    "-inf",    "+nan", "abc",
                                            "",    "1e400", "-1e400", "1e-4x",   "0x",   "--1",
                                            "one", "1e",    "1 2",    "\"1e-4\""};
const std::vector<std::string> kFiniteCells = {"1e308",  "-1e308", "1e30",  "-1e30",  "10",
                                               "-10",    "1",      "-1",    "1e-300", "0",
                                               "0x1p-3", " 1e-4 ", "+1e-4", "5e-324"};

CsvMutation mutate_csv(Rng& rng, std::string& text) {
  CsvMutation m;
  std::vector<std::string> lines = split_lines(text);
  if (lines.empty()) lines.push_back("");  // (a second mutation of an emptied file) so that header < size
  std::vector<std::size_t> rows;
  std::size_t header = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (is_data_row(lines[i])) rows.push_back(i);
    if (trim(lines[i]).starts_with("d_xx")) header = i;
  }
  const std::size_t op = rng.below(100);
  if (op < 25 && !rows.empty()) {  // one cell
    const std::size_t i = rng.pick(rows);
    std::vector<std::string> cells = split_cells(lines[i]);
    const std::size_t c = rng.below(cells.size());
    const bool bad = rng.chance(0.5);
    const std::string value = bad ? rng.pick(kBadCells) : rng.pick(kFiniteCells);
    m.words = "line " + std::to_string(i + 1) + " column " + std::to_string(c + 1) + ": " + cells[c] +
              " replaced by \"" + value + "\"";
    cells[c] = value;
    lines[i] = join_cells(cells);
    if (bad) {
      m.expect = Expect::InputError;
      m.why = "a cell that is not a finite number";
      m.line = static_cast<int>(i + 1);
    }
  } else if (op < 40 && !rows.empty()) {  // scale every increment (or one column)
    static const std::vector<double> factors = {1e2, 1e3, 1e5, -1e5, 1e8, 1e-300, 1e300};
    const double f = rng.pick(factors);
    const bool one_column = rng.chance(0.4);
    const std::size_t column = rng.below(6);
    for (std::size_t i : rows) {
      std::vector<std::string> cells = split_cells(lines[i]);
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (one_column && c != column) continue;
        double x = std::strtod(cells[c].c_str(), nullptr) * f;
        if (one_column && x == 0.0) x = f * 1e-4;  // a column of zeros becomes f times the shear increment
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", x);
        cells[c] = buf;
      }
      lines[i] = join_cells(cells);
    }
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", f);
    m.words = std::string(one_column ? "column " + std::to_string(column + 1) : "every increment") +
              " scaled by " + buf;
  } else if (op < 52 && !rows.empty()) {  // wrong column count
    const std::size_t i = rng.pick(rows);
    std::vector<std::string> cells = split_cells(lines[i]);
    const std::size_t which = rng.below(4);
    if (which == 0) {
      cells.pop_back();
      lines[i] = join_cells(cells);
      m.words = "line " + std::to_string(i + 1) + " has 5 cells";
    } else if (which == 1) {
      cells.push_back("0");
      lines[i] = join_cells(cells);
      m.words = "line " + std::to_string(i + 1) + " has 7 cells";
    } else if (which == 2) {
      lines[i] += ",";
      m.words = "line " + std::to_string(i + 1) + " ends with a comma";
    } else {
      lines[i] = "1e-4";
      m.words = "line " + std::to_string(i + 1) + " has 1 cell";
    }
    m.expect = Expect::InputError;
    m.why = "a row without 6 values";
    m.line = static_cast<int>(i + 1);
  } else if (op < 64) {  // empty, header only, header wrong or missing or repeated
    const std::size_t which = rng.below(6);
    m.expect = Expect::InputError;
    if (which == 0) {
      lines.clear();
      m.words = "empty file";
      m.why = "no header row";
    } else if (which == 1) {
      lines.resize(header + 1);
      m.words = "header only";
      m.why = "no increments";
    } else if (which == 2) {
      lines[header] = "d_xx,d_yy,d_zz,d_xy,d_yz";
      m.words = "header has 5 names";
      m.why = "the header row is not d_xx,...,d_xz";
      m.line = static_cast<int>(header + 1);
    } else if (which == 3) {
      lines.erase(lines.begin() + static_cast<long>(header));
      m.words = "header deleted";
      m.why = "the first row is not the header";
    } else if (which == 4) {
      const std::string copy = lines[header];
      lines.insert(lines.begin() + static_cast<long>(std::min(header + 2, lines.size())), copy);
      m.words = "header repeated as line " + std::to_string(header + 3);
      m.why = "a row of names is not numbers";
      m.line = static_cast<int>(header + 3);
    } else {
      lines = {"# only comments", "", "# nothing else"};
      m.words = "file of comments and blank lines";
      m.why = "no header row";
    }
  } else if (op < 72) {  // truncate
    const std::string whole = join_lines(lines);
    const std::size_t cut = rng.below(whole.size());
    text = whole.substr(0, cut);
    m.words = "file truncated to " + std::to_string(cut) + " of " + std::to_string(whole.size()) + " bytes";
    return m;
  } else if (op < 80) {  // garbage
    std::string whole = join_lines(lines);
    const std::size_t which = rng.below(3);
    if (which == 0) {
      const std::size_t at = rng.below(whole.size() + 1), n = 1 + rng.below(16);
      whole.insert(at, random_garbage(rng, n));
      m.words = std::to_string(n) + " garbage bytes inserted at byte " + std::to_string(at);
    } else if (which == 1) {
      whole = random_garbage(rng, 64 + rng.below(512));
      m.words = "file replaced by garbage bytes";
    } else {
      whole.insert(rng.below(whole.size() + 1), std::string(100000, '1'));
      m.words = "a run of 100000 '1' inserted";
    }
    text = whole;
    return m;
  } else if (op < 90) {  // harmless forms: CRLF, BOM, blank lines, comments, spaces
    const std::size_t which = rng.below(5);
    if (which == 0) {
      for (std::string& l : lines) l += '\r';
      m.words = "CRLF line ends";
    } else if (which == 1) {
      lines[0] = "\xEF\xBB\xBF" + lines[0];
      m.words = "UTF-8 byte-order mark at the start";
    } else if (which == 2) {
      for (std::size_t k = 0; k < 5; ++k)
        lines.insert(lines.begin() + static_cast<long>(rng.below(lines.size() + 1)), "");
      m.words = "blank lines inserted";
    } else if (which == 3) {
      lines.insert(lines.begin() + static_cast<long>(header + 1 + rng.below(lines.size() - header)),
                   "# a comment, with, commas");
      m.words = "a comment line inserted";
    } else {
      for (std::size_t i : rows) {
        std::vector<std::string> cells = split_cells(lines[i]);
        for (std::string& c : cells) c = " " + c + " \t";
        lines[i] = join_cells(cells);
      }
      m.words = "spaces and tabs around every cell";
    }
  } else {  // many rows
    const std::size_t times = 5 + rng.below(16);
    std::vector<std::string> more(lines.begin(), lines.begin() + static_cast<long>(header) + 1);
    for (std::size_t t = 0; t < times; ++t)
      for (std::size_t i : rows) more.push_back(lines[i]);
    lines = more;
    m.words = "the increments repeated " + std::to_string(times) + " times";
  }
  text = join_lines(lines);
  return m;
}

long long count_strain_rows(const std::string& text) {
  long long n = 0;
  bool header = false;
  for (const std::string& line : split_lines(text)) {
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    ++n;
  }
  return n;
}

// ---------------------------------------------------------------------------------------------------

const std::vector<std::string> kTests = {"triaxial-drained", "triaxial-undrained", "oedometer", "isotropic",
                                         "strain-path"};
const std::vector<std::string> kIntegrators = {"explicit", "substep", "implicit", "cvode"};

void add_point_options(Rng& rng, Case& c, const std::string& strain_path) {
  c.test = rng.pick(kTests);
  c.args.push_back("--test");
  c.args.push_back(c.test);
  if (c.test == "strain-path") {
    c.args.push_back("--strain-path");
    c.args.push_back(strain_path);
  } else {
    c.args.push_back("--increments");
    c.args.push_back("20");
  }
  if (rng.chance(0.3)) {
    const std::string integrator = rng.pick(kIntegrators);
    c.args.push_back("--integrator");
    c.args.push_back(integrator);
  }
}

/// The file mutations of one case; `file` is its name in the case folder.
void mutate_toml_file(Rng& rng, Case& c, const std::string& base_text, const std::string& file,
                      bool scene_file) {
  const toml::table parsed = toml::parse(base_text);
  std::string text = base_text;
  const std::size_t count = rng.chance(0.15) ? 2 + rng.below(2) : 1;
  TomlMutation single;
  for (std::size_t k = 0; k < count; ++k) {
    Doc doc = parse_doc(text);
    std::string out;
    const std::optional<toml::table> now = try_parse(text);
    single = mutate_toml(rng, doc, now ? *now : parsed, scene_file, out);
    text = out;
    c.mutations.push_back(single.words);
  }
  c.files.push_back({file, text});
  c.toml_path = file;
  c.names_if_input.push_back({"the file", {file}});
  if (count == 1) {
    c.expect = single.expect;
    c.expect_why = single.why;
    if (!single.keys.empty() && single.expect != Expect::Any)
      c.names_if_input.push_back({"the key", single.keys});
    // A value inside its own range may still be refused (it overflows something): the message must
    // then name the key (or one it bounds), not another.
    if (!single.keys.empty() && single.expect == Expect::Any)
      c.names_if_input.push_back({"the key", single.keys});
  }
  if (!try_parse(text)) {
    c.expect = Expect::InputError;
    c.expect_why = "toml++ rejects the file";
    if (c.names_if_input.size() > 1) c.names_if_input.resize(1);
  }
}

/// One command-line mutation of a point run (the material and the strain path unmutated).
void mutate_point_cli(Rng& rng, Case& c, const Inputs& in, const std::string& material_path,
                      const toml::table& material) {
  const std::size_t op = rng.below(100);
  auto replace_or_add = [&](const std::string& option, const std::string& value) {
    for (std::size_t k = 0; k + 1 < c.args.size(); ++k)
      if (c.args[k] == option) {
        c.args[k + 1] = value;
        return;
      }
    c.args.push_back(option);
    c.args.push_back(value);
  };
  const std::string csv = in.source_dir + "/data/strain-paths/simple-shear.csv";
  if (op < 30) {  // --set material.KEY=VALUE
    std::vector<const Spec*> material_specs;
    for (const Spec& s : specs())
      if (s.table == "material") material_specs.push_back(&s);
    const Spec& spec = *material_specs[rng.below(material_specs.size())];
    std::string how;
    std::string old = "1.0";
    if (const auto x = material["material"][spec.key].value<double>()) old = format_double(*x);
    const std::string value = pick_value(rng, &spec, old, &how);
    const std::string assignment = "material." + spec.key + "=" + value;
    c.args.push_back("--set");
    c.args.push_back(assignment);
    c.overrides.push_back(assignment);
    c.mutations.push_back("--set " + assignment + " (" + how + ")");
    std::vector<std::string> keys = {spec.key};
    for (const std::string& d : spec.dependents) keys.push_back(d);
    c.names_if_input = {{"the option", {"--set"}}, {"the key", keys}};
    // --set parses VALUE as TOML, else takes it as a bare string unless it starts with [ or {.
    std::optional<toml::table> v = try_parse("v = " + value);
    if (!v && (value.starts_with('[') || value.starts_with('{'))) {
      c.expect = Expect::InputError;
      c.expect_why = "--set value that starts like an array or table but is not TOML";
      return;
    }
    if (!v) {
      v = toml::table{};
      v->insert_or_assign("v", value);
    }
    toml::table after = material;
    if (auto* t = after["material"].as_table()) t->insert_or_assign(spec.key, *v->get("v"));
    if (material_key_used(after, spec.key)) {
      c.expect = judge(spec, *v->get("v"), material);
      if (c.expect == Expect::InputError) c.expect_why = "the value is not admissible for " + spec.key;
    }
    return;
  }
  if (op < 40) {  // malformed or misdirected --set
    static const std::vector<std::string> forms = {"material.young_modulus",
                                                   "young_modulus=1",
                                                   "=1",
                                                   "material.=1",
                                                   "material.young_modulus=[1,",
                                                   "material.young_modulus={",
                                                   "material.young_modulus=",
                                                   "foo.bar=1",
                                                   "material.unknown_key=1",
                                                   "material=1",
                                                   "material.young_modulus.x=1"};
    const std::string form = rng.pick(forms);
    c.args.push_back("--set");
    c.args.push_back(form);
    c.overrides.push_back(form);
    c.mutations.push_back("--set " + form + " (malformed or unknown)");
    c.expect = Expect::InputError;
    c.expect_why = "not a valid --set for a material";
    c.names_if_input = {{"the option", {"--set"}}};
    return;
  }
  struct Option {
    std::string name;
    std::vector<std::pair<std::string, Expect>> values;
  };
  using E = Expect;
  static const std::vector<Option> options = {
      {"--p-initial",
       {{"0", E::InputError},
        {"-1", E::InputError},
        {"-0", E::InputError},
        {"nan", E::InputError},
        {"inf", E::InputError},
        {"-inf", E::InputError},
        {"1e308", E::Any},
        {"5e-324", E::Any},
        {"1e-300", E::Any},
        {"abc", E::InputError},
        {"", E::InputError},
        {"1e400", E::InputError}}},
      {"--ocr",
       {{"0.5", E::InputError},
        {"0", E::InputError},
        {"-1", E::InputError},
        {"0.999999", E::InputError},
        {"nan", E::InputError},
        {"inf", E::InputError},
        {"1e308", E::Any},
        {"abc", E::InputError},
        {"2", E::Any},
        {"1000", E::Any}}},
      {"--strain-max",
       {{"0", E::InputError},
        {"nan", E::InputError},
        {"inf", E::InputError},
        {"-inf", E::InputError},
        {"1e6", E::InputError},
        {"1", E::InputError},
        {"2", E::InputError},
        {"-0.1", E::Any},
        {"-1e6", E::Any},
        {"0.1,,0.2", E::InputError},
        {"0.1,0.05,0.15", E::Any},
        {"abc", E::InputError},
        {"1e400", E::InputError},
        {"5e-324", E::Any}}},
      {"--increments",
       {{"0", E::InputError},
        {"-1", E::InputError},
        {"2.5", E::InputError},
        {"abc", E::InputError},
        {"1e9", E::InputError},
        {"99999999999", E::InputError},
        {"", E::InputError},
        {"2147483647", E::Any}}},
      {"--integrator", {{"bogus", E::InputError}, {"Explicit", E::InputError}, {"", E::InputError}}},
      {"--test",
       {{"bogus", E::InputError},
        {"", E::InputError},
        {"Triaxial-drained", E::InputError},
        {"strain-path", E::InputError}}},
      {"--strain-path", {{"missing.csv", E::InputError}, {"CSV_WITH_OTHER_TEST", E::InputError}}},
      {"--bogus", {{"1", E::InputError}}},
      {"MATERIAL", {{"missing.toml", E::InputError}}},
  };
  const Option& option = options[rng.below(options.size())];
  const auto& [value, expect] = option.values[rng.below(option.values.size())];
  c.expect = expect;
  c.expect_why = expect == E::InputError ? option.name + " " + value + " is not admissible" : "";
  c.names_if_input = {{"the option", {option.name}}};
  if (option.name == "--test") {
    // --test strain-path without --strain-path: the message may name either option.
    c.args = {"point", material_path, "--test", value};
    if (value != "strain-path") c.args.insert(c.args.end(), {"--increments", "20"});
    c.test = value;
    c.names_if_input = {{"the option", {"--test", "--strain-path"}}};
  } else if (option.name == "--strain-path") {
    if (value == "missing.csv") {
      c.args = {"point", material_path, "--test", "strain-path", "--strain-path", "missing.csv"};
      c.names_if_input = {{"the file", {"missing.csv"}}};
      c.test = "strain-path";
    } else {
      c.args = {"point", material_path, "--test", "oedometer", "--strain-path", csv};
      c.names_if_input = {{"the option", {"--strain-path"}}};
      c.test = "oedometer";
    }
  } else if (option.name == "MATERIAL") {
    c.args[1] = value;
    c.names_if_input = {{"the file", {value}}};
  } else if (option.name == "--increments" && c.test == "strain-path") {
    // --increments does not apply to a strain path: an input error whatever the value.
    replace_or_add(option.name, value);
    c.expect = E::InputError;
    c.expect_why = "--increments does not apply to --test strain-path";
    c.names_if_input = {{"the option", {"--increments"}}};
  } else if (option.name == "--strain-max" && c.test == "strain-path") {
    replace_or_add(option.name, value);
    c.expect = E::InputError;
    c.expect_why = "--strain-max does not apply to --test strain-path";
  } else if (option.name == "--bogus") {
    c.args.push_back("--bogus");
    c.args.push_back("1");
  } else {
    replace_or_add(option.name, value);
  }
  if (option.name == "MATERIAL")
    c.mutations.push_back("material file " + value + " does not exist");
  else if (value == "CSV_WITH_OTHER_TEST")
    c.mutations.push_back("--strain-path FILE with --test oedometer");
  else if (option.name == "--test" && value == "strain-path")
    c.mutations.push_back("--test strain-path without --strain-path");
  else
    c.mutations.push_back(option.name + " " + (value.empty() ? "\"\"" : value));
  // What the output checks need to know of the options as run.
  if (option.name == "--p-initial" && expect == E::Any) c.p_initial = std::strtod(value.c_str(), nullptr);
  if (option.name == "--ocr" && expect == E::Any) {
    c.ocr = std::strtod(value.c_str(), nullptr);
    c.ocr_given = true;
  }
  if (option.name == "--strain-max" && expect == E::Any)
    c.legs = value.find(',') == std::string::npos ? 1 : 3;
  if (option.name == "--increments" && expect == E::Any)
    c.increments = std::strtoll(value.c_str(), nullptr, 10);
}

void mutate_collapse_cli(Rng& rng, Case& c, const toml::table& scene) {
  const std::size_t op = rng.below(100);
  if (op < 45) {  // --set TABLE.KEY=VALUE
    const Spec& spec = specs()[rng.below(specs().size())];
    std::string how;
    std::string old = "1.0";
    if (const auto x = scene[spec.table][spec.key].value<double>()) old = format_double(*x);
    const std::string value = pick_value(rng, &spec, old, &how);
    const std::string assignment = spec.table + "." + spec.key + "=" + value;
    c.args.push_back("--set");
    c.args.push_back(assignment);
    c.overrides.push_back(assignment);
    c.mutations.push_back("--set " + assignment + " (" + how + ")");
    std::vector<std::string> keys = {spec.key};
    for (const std::string& d : spec.dependents) keys.push_back(d);
    c.names_if_input = {{"the option", {"--set"}}, {"the key", keys}};
    std::optional<toml::table> v = try_parse("v = " + value);
    if (!v && (value.starts_with('[') || value.starts_with('{'))) {
      c.expect = Expect::InputError;
      c.expect_why = "--set value that starts like an array or table but is not TOML";
      return;
    }
    if (!v) {
      v = toml::table{};
      v->insert_or_assign("v", value);
    }
    toml::table after = scene;
    if (auto* t = after[spec.table].as_table()) t->insert_or_assign(spec.key, *v->get("v"));
    if (spec.table != "material" || material_key_used(after, spec.key)) {
      c.expect = judge(spec, *v->get("v"), scene);
      if (c.expect == Expect::InputError) c.expect_why = "the value is not admissible for " + spec.key;
    }
    return;
  }
  if (op < 60) {
    static const std::vector<std::string> forms = {
        "scene.end_time",  "end_time=1",         "=1",
        "scene.=1",        "scene.end_time=[1,", "output.fields={",
        "scene.end_time=", "foo.bar=1",          "scene.unknown_key=1",
        "scene=1",         "scene.end_time.x=1"};
    const std::string form = rng.pick(forms);
    c.args.push_back("--set");
    c.args.push_back(form);
    c.overrides.push_back(form);
    c.mutations.push_back("--set " + form + " (malformed or unknown)");
    c.expect = Expect::InputError;
    c.expect_why = "not a valid --set for a scene";
    c.names_if_input = {{"the option", {"--set"}}};
    return;
  }
  if (op < 80) {
    static const std::vector<std::pair<std::string, Expect>> threads = {
        {"0", Expect::InputError},   {"-1", Expect::InputError},
        {"2.5", Expect::InputError}, {"abc", Expect::InputError},
        {"", Expect::InputError},    {"1000", Expect::Any},
        {"auto", Expect::Any},       {"99999999999", Expect::InputError},
        {"1e3", Expect::InputError}};
    const auto& [value, expect] = rng.pick(threads);
    for (std::size_t k = 0; k + 1 < c.args.size(); ++k)
      if (c.args[k] == "--threads") c.args[k + 1] = value;
    c.mutations.push_back("--threads " + (value.empty() ? std::string("\"\"") : value));
    c.expect = expect;
    c.expect_why = expect == Expect::InputError ? "--threads " + value + " is not admissible" : "";
    c.names_if_input = {{"the option", {"--threads"}}};
    return;
  }
  const std::size_t which = rng.below(4);
  if (which == 0) {  // --out is an existing file
    c.files.push_back({"blocker", "a file where the output folder should be\n"});
    for (std::size_t k = 0; k + 1 < c.args.size(); ++k)
      if (c.args[k] == "--out") c.args[k + 1] = "blocker";
    c.out_dir = "blocker";
    c.mutations.push_back("--out names an existing regular file");
    c.expect = Expect::Failure;
    c.expect_why = "the output folder cannot be created";
    c.names_if_failed = {{"the folder", {"blocker"}}};
  } else if (which == 1) {  // --out cannot be created
    for (std::size_t k = 0; k + 1 < c.args.size(); ++k)
      if (c.args[k] == "--out") c.args[k + 1] = "/proc/soilsph-fuzz/out";
    c.out_dir = "/proc/soilsph-fuzz/out";
    c.mutations.push_back("--out in a folder that cannot be written");
    c.expect = Expect::Failure;
    c.expect_why = "the output folder cannot be created";
    c.names_if_failed = {{"the folder", {"/proc/soilsph-fuzz/out"}}};
  } else if (which == 2) {
    c.args[1] = "missing.toml";
    c.mutations.push_back("scene file missing.toml does not exist");
    c.expect = Expect::InputError;
    c.expect_why = "the scene file does not exist";
    c.names_if_input = {{"the file", {"missing.toml"}}};
  } else {
    c.args.push_back("--bogus");
    c.mutations.push_back("unknown option --bogus");
    c.expect = Expect::InputError;
    c.expect_why = "--bogus is not an option";
    c.names_if_input = {{"the option", {"--bogus"}}};
  }
}

}  // namespace

std::string small_scene(const std::string& scene_toml, const std::string& spacing) {
  Doc doc = parse_doc(scene_toml);
  for (std::size_t i = 0; i < doc.lines.size(); ++i) {
    Line& line = doc.lines[i];
    if (line.table == "scene" && line.key == "particle_spacing") set_value(line, spacing);
    if (line.table == "output" && line.key == "frame_interval") set_value(line, "0.01");
    if (line.table == "scene" && line.key == "end_time") {
      set_value(line, "0.02");
      // A budget that an admissible but slow mutant (cfl 5e-4, nu = 0.4999999) exceeds: refused up
      // front by the run-time estimate rather than counted as a hang. The unmutated run is 0.1 s.
      doc.lines.insert(doc.lines.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                       text_line("max_run_hours = 0.002"));
    }
  }
  doc.lines.insert(doc.lines.begin(),
                   text_line("# soilsph input fuzzer: a small, short copy of the shipped scene"));
  return render(doc);
}

/// A shipped programme as a fuzz case's file: its `material = "../materials/X.toml"`, relative to the
/// programme's folder, made absolute (the case runs in a folder of its own).
std::string programme_with_absolute_material(const std::string& text, const std::string& programmes_dir) {
  const std::string key = "material = \"";
  const std::size_t at = text.find(key);
  if (at == std::string::npos || text.compare(at + key.size(), 1, "/") == 0) return text;
  return text.substr(0, at + key.size()) + programmes_dir + "/" + text.substr(at + key.size());
}

Inputs Inputs::load(const std::string& source_dir) {
  Inputs in;
  in.source_dir = source_dir;
  in.material_dp = read_file(source_dir + "/data/materials/dp-table1.toml");
  in.material_mcc = read_file(source_dir + "/data/materials/mcc-table1.toml");
  in.strain_csv = read_file(source_dir + "/data/strain-paths/simple-shear.csv");
  in.scene_dp = small_scene(read_file(source_dir + "/data/scenes/collapse-dp.toml"));
  in.scene_mcc = small_scene(read_file(source_dir + "/data/scenes/collapse-mcc.toml"));
  const auto scene = [&](const std::string& name, const std::string& spacing) {
    return SceneInput{"scene-" + name + ".toml",
                      small_scene(read_file(source_dir + "/data/scenes/" + name + ".toml"), spacing),
                      {}};
  };
  for (const char* name :
       {"collapse-mc", "gate-lift", "slope", "two-material-column", "sphinxsys-column-collapse"})
    in.other_scenes.push_back(scene(name, "0.004"));
  in.other_scenes.push_back(scene("vertical-cut", "0.005"));  // its 3 cm cut does not divide by 4 mm
  // The imported column samples its CSV at 4 mm, which the scene's spacing must keep.
  in.other_scenes.push_back(scene("imported-column", "0.004"));
  in.other_scenes.back().files = {
      {"imported-column.csv", read_file(source_dir + "/data/scenes/imported-column.csv")}};
  const std::string programmes_dir = source_dir + "/data/programmes";
  for (const auto& entry : std::filesystem::directory_iterator(programmes_dir))
    if (entry.path().extension() == ".toml")
      in.programmes.emplace_back(
          entry.path().filename().string(),
          programme_with_absolute_material(read_file(entry.path().string()), programmes_dir));
  std::sort(in.programmes.begin(), in.programmes.end());  // a case is a function of (seed, index) alone
  return in;
}

/// The scene of a collapse case: the D-P or MCC column, or (30 %) another shipped scene.
SceneInput collapse_scene(Rng& rng, const Inputs& in, bool dp) {
  if (!in.other_scenes.empty() && rng.chance(0.3)) return in.other_scenes[rng.below(in.other_scenes.size())];
  return dp ? SceneInput{"scene-dp.toml", in.scene_dp, {}} : SceneInput{"scene-mcc.toml", in.scene_mcc, {}};
}

Case make_case(const Inputs& in, std::uint64_t seed, std::uint64_t index) {
  Rng rng(seed * 0x2545F4914F6CDD1Dull ^ (index + 1) * 0x9E3779B97F4A7C15ull);
  rng.next();
  Case c;
  c.seed = seed;
  c.index = index;
  const bool dp = rng.chance(0.5);
  const std::string material_name = dp ? "dp-table1.toml" : "mcc-table1.toml";
  const std::string material_text = dp ? in.material_dp : in.material_mcc;
  const std::string material_path = in.source_dir + "/data/materials/" + material_name;
  const std::string csv_path = in.source_dir + "/data/strain-paths/simple-shear.csv";
  const std::size_t kind = rng.below(100);
  if (kind < 14) {
    c.kind = "material";
    c.command = "material";
    c.args = {"material", material_name};
    mutate_toml_file(rng, c, material_text, material_name, false);
  } else if (kind < 32) {
    c.kind = "point";
    c.command = "point";
    c.args = {"point", material_name};
    add_point_options(rng, c, csv_path);
    c.strain_rows = count_strain_rows(in.strain_csv);
    mutate_toml_file(rng, c, material_text, material_name, false);
  } else if (kind < 46) {
    c.kind = "strain-path";
    c.command = "point";
    c.test = "strain-path";
    c.toml_path = material_path;
    std::string text = in.strain_csv;
    const std::size_t count = rng.chance(0.15) ? 2 : 1;
    CsvMutation single;
    for (std::size_t k = 0; k < count; ++k) {
      single = mutate_csv(rng, text);
      c.mutations.push_back(single.words);
    }
    c.files.push_back({"strain-path.csv", text});
    c.args = {"point", material_path, "--test", "strain-path", "--strain-path", "strain-path.csv"};
    if (rng.chance(0.4)) {
      c.args.push_back("--integrator");
      c.args.push_back(rng.pick(kIntegrators));
    }
    c.strain_rows = count_strain_rows(text);
    // Whatever the exit, a failure on a strain path must say which file.
    c.names_if_failed = {{"the strain-path file", {"strain-path.csv"}}};
    if (count == 1) {
      c.expect = single.expect;
      c.expect_why = single.why;
      if (single.line > 0)
        c.names_if_input.push_back({"the file and line", {"strain-path.csv:" + std::to_string(single.line)}});
    }
  } else if (kind < 58 && !in.programmes.empty()) {
    // A shipped programme file mutated like the other TOML inputs (docs/reference/programmes.md), run as it
    // is or with another integrator; its output is checked for shape and finite values only.
    c.kind = "programme";
    c.command = "point";
    const auto& [name, text] = in.programmes[rng.below(in.programmes.size())];
    c.args = {"point", name};
    if (rng.chance(0.3)) {
      c.args.push_back("--integrator");
      c.args.push_back(rng.pick(kIntegrators));
    }
    mutate_toml_file(rng, c, text, name, false);
  } else if (kind < 88) {
    c.kind = "collapse";
    c.command = "collapse";
    const SceneInput scene = collapse_scene(rng, in, dp);
    c.args = {"collapse", scene.name, "--out", "out", "--threads", "1"};
    c.out_dir = "out";
    if (!scene.files.empty() && rng.chance(0.5)) {
      // The file the scene reads (the imported particles), mutated like the strain-path CSV; what it
      // may rightly hold differs (x, y, a region name), so only the contract is judged: a refusal
      // names the file.
      File data = scene.files.front();
      c.mutations.push_back(mutate_csv(rng, data.content).words);
      c.files = {data, {scene.name, scene.text}};
      c.toml_path = scene.name;
      c.names_if_input = {{"the file", {data.name}}};
    } else {
      c.files = scene.files;
      mutate_toml_file(rng, c, scene.text, scene.name, true);
    }
  } else if (kind < 95) {
    c.kind = "cli-point";
    c.command = "point";
    c.toml_path = material_path;
    c.args = {"point", material_path};
    add_point_options(rng, c, csv_path);
    c.strain_rows = count_strain_rows(in.strain_csv);
    mutate_point_cli(rng, c, in, material_path, toml::parse(material_text));
  } else {
    c.kind = "cli-collapse";
    c.command = "collapse";
    const SceneInput scene = collapse_scene(rng, in, dp);
    c.files = scene.files;
    c.files.push_back({scene.name, scene.text});
    c.toml_path = scene.name;
    c.args = {"collapse", scene.name, "--out", "out", "--threads", "1"};
    c.out_dir = "out";
    mutate_collapse_cli(rng, c, toml::parse(scene.text));
  }
  return c;
}

std::vector<Case> base_cases(const Inputs& in) {
  std::vector<Case> cases;
  const std::string csv_path = in.source_dir + "/data/strain-paths/simple-shear.csv";
  for (const bool dp : {true, false}) {
    const std::string name = dp ? "dp-table1.toml" : "mcc-table1.toml";
    const std::string text = dp ? in.material_dp : in.material_mcc;
    Case m;
    m.kind = "material";
    m.command = "material";
    m.mutations = {"none"};
    m.files = {{name, text}};
    m.toml_path = name;
    m.args = {"material", name};
    cases.push_back(m);
    for (const std::string& test : kTests) {
      for (const std::string& integrator : kIntegrators) {
        Case p = m;
        p.kind = "point";
        p.command = "point";
        p.test = test;
        p.args = {"point", name, "--test", test, "--integrator", integrator};
        if (test == "strain-path") {
          p.args.insert(p.args.end(), {"--strain-path", csv_path});
          p.strain_rows = count_strain_rows(in.strain_csv);
        } else {
          p.args.insert(p.args.end(), {"--increments", "20"});
        }
        cases.push_back(p);
      }
    }
    Case o = m;  // legs and OCR
    o.kind = "point";
    o.command = "point";
    o.test = "triaxial-drained";
    o.args = {"point", name, "--test", o.test, "--increments", "20", "--strain-max", "0.1,0.05,0.15"};
    o.legs = 3;
    if (!dp) {
      o.args.insert(o.args.end(), {"--ocr", "2"});
      o.ocr = 2;
      o.ocr_given = true;
    }
    cases.push_back(o);
    Case s;
    s.kind = "collapse";
    s.command = "collapse";
    s.mutations = {"none"};
    const std::string scene = dp ? "scene-dp.toml" : "scene-mcc.toml";
    s.files = {{scene, dp ? in.scene_dp : in.scene_mcc}};
    s.toml_path = scene;
    s.args = {"collapse", scene, "--out", "out", "--threads", "1"};
    s.out_dir = "out";
    cases.push_back(s);
  }
  for (const SceneInput& scene : in.other_scenes) {
    Case s;
    s.kind = "collapse";
    s.command = "collapse";
    s.mutations = {"none"};
    s.files = scene.files;
    s.files.push_back({scene.name, scene.text});
    s.toml_path = scene.name;
    s.args = {"collapse", scene.name, "--out", "out", "--threads", "1"};
    s.out_dir = "out";
    cases.push_back(s);
  }
  for (std::size_t k = 0; k < cases.size(); ++k) cases[k].index = k;
  return cases;
}

}  // namespace soilsph::fuzz
