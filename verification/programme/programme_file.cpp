#include "verification/programme/programme_file.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <numbers>
#include <sstream>

#include "constitutive/admissible_state.h"
#include "constitutive/material_description.h"
#include "constitutive/material_limits.h"
#include "constitutive/parameters.h"
#include "verification/driver/rate_independence.h"

namespace soilsph::verification {

namespace {
namespace fs = std::filesystem;

constexpr std::string_view kComponents[6] = {"xx", "yy", "zz", "xy", "yz", "xz"};  // Voigt order
constexpr double kHold = NAN;  ///< a stress target "hold": keep the value reached

/// The material: a path relative to the programme, or an inline [material] table; --set applies to it.
Material read_programme_material(const toml::table& root, const std::string& path,
                                 std::span<const std::string> overrides, std::string& source) {
  const toml::node* node = root.get("material");
  if (!node) throw ParameterError(path + ": no material (material = \"FILE\" or a [material] table)");
  toml::table holder;
  if (const auto file = node->value<std::string>()) {
    source = (fs::path(path).parent_path() / *file).lexically_normal().string();
    if (!fs::exists(source)) throw ParameterError(path + ": material = \"" + *file + "\": no such file (" + source + ")");
    holder = parse_toml_file(source);
  } else if (const toml::table* inline_table = node->as_table()) {
    source = path;
    holder.insert("material", *inline_table);
  } else {
    throw ParameterError(path + ": material must be a file name or a [material] table");
  }
  for (const std::string& assignment : overrides) {
    const std::size_t dot = assignment.find('.');
    if (dot < assignment.find('=') && assignment.compare(0, dot, "material") != 0)
      throw ParameterError("--set " + assignment + ": a programme's --set may only address its material (--set material.KEY=VALUE)");
    apply_override(holder, assignment);
  }
  const toml::table* table = holder["material"].as_table();
  if (!table) throw ParameterError(source + ": no [material] table");
  const Material material =
      blaming_overrides(overrides, [&] { return read_material(TableReader(*table, source, "material")); });
  warn_if_rate_dependent(material, source);
  return material;
}

/// K0 when none is given: Jaky's 1 − sin φ, times OCR^sin φ on unloading (Mayne & Kulhawy 1982), for
/// models with a friction angle; the elastic ν/(1−ν) otherwise.
double default_lateral_stress_ratio(const Material& material, double ocr) {
  return std::visit(
      [ocr](const auto& model) {
        if constexpr (requires { model.params().friction_angle; }) {
          const double sin_phi = std::sin(model.params().friction_angle * std::numbers::pi / 180.0);
          return (1.0 - sin_phi) * std::pow(ocr, sin_phi);
        } else {
          const double nu = model.elasticity().poisson_ratio();  // a UMAT's from its DDSDDE
          return nu / (1.0 - nu);
        }
      },
      material);
}

State read_initial(const TableReader& t, const Material& material, std::string& text) {
  const double ocr = t.number_or("ocr", 1.0, point_limits::ocr());
  if (ocr != 1.0 && !has_preconsolidation(material))
    t.fail("ocr", "applies to models with a preconsolidation pressure (" + preconsolidation_models() + ") only");
  State s;
  std::ostringstream out;
  if (t.has("p") == t.has("vertical_stress"))
    t.fail("p", "give either p (isotropic) or vertical_stress (K0), not both or neither");
  if (t.has("p")) {
    const double p = t.number("p", point_limits::p_initial(), "Pa");
    if (t.has("lateral_stress_ratio")) t.fail("lateral_stress_ratio", "applies with vertical_stress only");
    s.stress = isotropic_stress(p);
    out << "isotropic p = " << exact_number(p) << " Pa";
  } else {
    const double v = t.number("vertical_stress", point_limits::p_initial(), "Pa");
    const double k0 =
        t.number_or("lateral_stress_ratio", default_lateral_stress_ratio(material, ocr), Range::open_closed(0.0, 10.0));
    s.stress = Mat3::Zero();
    s.stress.diagonal() << -v, -k0 * v, -k0 * v;
    out << "K0 state: vertical_stress = " << exact_number(v) << " Pa, lateral_stress_ratio = " << exact_number(k0);
  }
  s.pc = initial_preconsolidation(material, s.stress, ocr);
  if (has_preconsolidation(material)) out << ", ocr = " << exact_number(ocr) << " (p_c = " << exact_number(s.pc) << " Pa)";
  if (!std::visit([&s](const auto& model) { return admissible_state(model, s); }, material))
    t.fail(t.has("p") ? "p" : "lateral_stress_ratio", "gives an initial state outside the yield surface");
  t.reject_unknown_keys();
  text = out.str();
  return s;
}

/// One component's targets: a number, "hold" (stress only) or a list of them.
std::vector<double> read_targets(const toml::node& node, const std::string& where, bool stress) {
  const Range range = stress ? Range::closed(-limits::kMaxStress, limits::kMaxStress) : point_limits::strain();
  const auto one = [&](const toml::node& n) {
    if (stress && n.value<std::string>() == "hold") return kHold;
    const std::optional<double> x = n.is_boolean() ? std::nullopt : n.value<double>();
    if (!x) throw ParameterError(where + " must be a number" + (stress ? ", \"hold\"" : "") + " or a list of them");
    if (!range.contains(*x))
      throw ParameterError(where + " = " + format_number(*x) + " is out of range (allowed: " + range.describe() +
                           (stress ? " Pa)" : ")"));
    return *x;
  };
  std::vector<double> targets;
  if (const toml::array* list = node.as_array()) {
    if (list->empty()) throw ParameterError(where + " is an empty list");
    for (const toml::node& n : *list) targets.push_back(one(n));
  } else {
    targets.push_back(one(node));
  }
  return targets;
}

/// The legs of one [[leg]] table: its targets in turn, `repeat` times.
void read_leg(const toml::table& table, const std::string& path, std::size_t index, Programme& programme) {
  const std::string name = "leg " + std::to_string(index + 1);
  const TableReader t(table, path, name);
  const std::string label = table["name"].value<std::string>().value_or("");
  t.accept({"name", "strain", "stress"});
  const bool undrained = t.choice_or("drainage", "drained", {"drained", "undrained"}) == "undrained";
  const int increments = static_cast<int>(t.integer_or("increments", 100, 1, point_limits::kMaxIncrements));
  const int repeat = static_cast<int>(t.integer_or("repeat", 1, 1, 10000));
  t.reject_unknown_keys();

  std::array<std::vector<double>, 6> targets;  // per component; empty: strain held
  std::array<bool, 6> stress_imposed{};
  std::size_t count = 1;
  for (const bool stress : {false, true}) {
    const std::string kind = stress ? "stress" : "strain";
    const toml::node* node = table.get(kind);
    if (!node) continue;
    const toml::table* components = node->as_table();
    const std::string where = path + ": [" + name + "] " + kind;
    if (!components) throw ParameterError(where + " must be a table, e.g. " + kind + " = { xx = 0.1 }");
    for (const auto& [key, value] : *components) {
      const auto* it = std::find(std::begin(kComponents), std::end(kComponents), key.str());
      if (it == std::end(kComponents))
        throw ParameterError(where + "." + std::string(key.str()) + " is not a component (allowed: xx, yy, zz, xy, yz, xz)");
      const auto k = static_cast<std::size_t>(it - std::begin(kComponents));
      if (!targets[k].empty())
        throw ParameterError(where + "." + std::string(key.str()) + ": the component has a strain and a stress");
      targets[k] = read_targets(value, where + "." + std::string(key.str()), stress);
      stress_imposed[k] = stress;
      if (targets[k].size() > 1) {
        if (count > 1 && targets[k].size() != count)
          throw ParameterError(where + "." + std::string(key.str()) + ": a list of " + std::to_string(targets[k].size()) +
                               " targets where another has " + std::to_string(count));
        count = targets[k].size();
      }
    }
  }
  if (undrained && !stress_imposed[0] && !stress_imposed[1] && !stress_imposed[2])
    throw ParameterError(path + ": [" + name + "] an undrained leg needs a stress on a normal component (xx, yy "
                         "or zz; \"hold\" will do): with every normal strain imposed the pore pressure is not defined");
  for (int cycle = 0; cycle < repeat; ++cycle) {
    for (std::size_t n = 0; n < count; ++n) {
      Leg leg;
      leg.increments = increments;
      leg.undrained = undrained;
      leg.stress_imposed = stress_imposed;
      for (std::size_t k = 0; k < 6; ++k) {
        if (targets[k].empty()) continue;  // strain held: zero increment
        const double value = targets[k][targets[k].size() == 1 ? 0 : n];
        leg.target[k] = -value;  // compression-positive input, tension-positive Voigt (γ = 2ε)
      }
      programme.legs.push_back(leg);
      std::string text = name + (label.empty() ? "" : " (" + label + ")");
      if (count > 1) text += ", target " + std::to_string(n + 1) + " of " + std::to_string(count);
      if (repeat > 1) text += ", cycle " + std::to_string(cycle + 1) + " of " + std::to_string(repeat);
      programme.leg_names.push_back(text + " of " + path);
    }
  }
}
}  // namespace

bool is_programme_file(const std::string& path) {
  try {
    return parse_toml_file(path).contains("leg");
  } catch (const ParameterError&) {
    return false;  // the material reader will report it
  }
}

ProgrammeFile read_programme_file(const std::string& path, std::span<const std::string> overrides) {
  return read_programme(parse_toml_file(path), path, overrides);
}

ProgrammeFile read_programme(const toml::table& root, const std::string& path, std::span<const std::string> overrides) {
  for (const auto& [key, value] : root) {
    if (key.str() != "material" && key.str() != "initial" && key.str() != "leg" && key.str() != "path_tolerance")
      throw ParameterError(path + ": " + std::string(key.str()) +
                           " is not a known key or table (allowed: material, path_tolerance, [initial], [[leg]])");
  }
  std::string material_source;
  ProgrammeFile file{read_programme_material(root, path, overrides, material_source), material_source, {}, {}};
  if (root.contains("path_tolerance")) {  // driver sub-steps (path_substeps.h); absent or 0: off
    const std::optional<double> tolerance = root["path_tolerance"].value<double>();
    const std::string allowed = "(allowed: 0 (off) or " + point_limits::path_tolerance().describe() + ")";
    if (!tolerance) throw ParameterError(path + ": path_tolerance must be a number " + allowed);
    if (*tolerance != 0.0 && !point_limits::path_tolerance().contains(*tolerance))
      throw ParameterError(path + ": path_tolerance = " + format_number(*tolerance) + " is out of range " + allowed);
    file.programme.path_tolerance = *tolerance;
  }
  const toml::table* initial = root["initial"].as_table();
  if (!initial) throw ParameterError(path + ": no [initial] table");
  std::string initial_text;
  file.programme.initial = read_initial(TableReader(*initial, path, "initial"), file.material, initial_text);
  const toml::array* legs = root["leg"].as_array();
  if (!legs || legs->empty() || !legs->is_array_of_tables())
    throw ParameterError(path + ": no [[leg]] tables");
  for (std::size_t i = 0; i < legs->size(); ++i) read_leg(*legs->get(i)->as_table(), path, i, file.programme);
  long long increments = 0;
  for (const Leg& leg : file.programme.legs) increments += leg.increments;
  if (increments > 10LL * point_limits::kMaxIncrements)
    throw ParameterError(path + ": " + std::to_string(increments) + " increments in all, more than " +
                         std::to_string(10LL * point_limits::kMaxIncrements) + " (fewer increments or repeats)");
  file.description = path + ": " + initial_text + "; " + std::to_string(legs->size()) + " [[leg]] table(s), " +
                     std::to_string(file.programme.legs.size()) + " legs, " + std::to_string(increments) +
                     " increments";
  return file;
}

}  // namespace soilsph::verification
