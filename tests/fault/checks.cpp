// The contract checks of one case's outcome: how it ended, its message, and (on exit 0) its results.
#include <toml++/toml.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

#include "tests/fault/fuzz.h"

namespace soilsph::fuzz {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

std::string first_line_starting(const std::string& text, std::string_view prefix) {
  for (const std::string& line : lines_of(text))
    if (line.starts_with(prefix)) return line;
  return "";
}

/// The whole text as a number (strtod), or nullopt.
std::optional<double> to_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return x;
}

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

/// The case's TOML input as the command saw it: the file with the --set overrides applied the way
/// the command line documents them (a TOML value, else a bare string). nullopt if it is not TOML.
std::optional<toml::table> effective_toml(const Case& c, const fs::path& dir) {
  if (c.toml_path.empty()) return std::nullopt;
  const fs::path path = fs::path(c.toml_path).is_absolute() ? fs::path(c.toml_path) : dir / c.toml_path;
  toml::table root;
  try {
    root = toml::parse_file(path.string());
  } catch (const std::exception&) {
    return std::nullopt;
  }
  for (const std::string& a : c.overrides) {
    const std::size_t eq = a.find('='), dot = a.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot > eq) continue;
    const std::string section = a.substr(0, dot), key = a.substr(dot + 1, eq - dot - 1),
                      text = a.substr(eq + 1);
    if (!root.contains(section)) root.insert_or_assign(section, toml::table{});
    toml::table* t = root[section].as_table();
    if (!t) continue;
    try {
      toml::table v = toml::parse("v = " + text);
      t->insert_or_assign(key, *v.get("v"));
    } catch (const toml::parse_error&) {
      t->insert_or_assign(key, text);
    }
  }
  return root;
}

double num(const toml::table& doc, std::string_view table, std::string_view key, double fallback) {
  const toml::node* n = doc[table][key].node();
  if (!n || n->is_boolean()) return fallback;
  return n->value<double>().value_or(fallback);
}

std::string str(const toml::table& doc, std::string_view table, std::string_view key,
                const std::string& fallback) {
  return doc[table][key].value_exact<std::string>().value_or(fallback);
}

/// The integrator a point run without --integrator uses: its material's `integrator` key (a
/// programme's material may be a file of its own, named relative to the programme), else implicit.
std::string material_integrator(const Case& c, const fs::path& dir) {
  std::optional<toml::table> doc = effective_toml(c, dir);
  if (!doc) return "implicit";
  if (const std::optional<std::string> file = (*doc)["material"].value_exact<std::string>()) {
    const fs::path path = fs::path(*file).is_absolute() ? fs::path(*file) : dir / *file;
    try {
      doc = toml::parse_file(path.string());
    } catch (const std::exception&) {
      return "implicit";
    }
  }
  return str(*doc, "material", "integrator", "implicit");
}

// ---------------------------------------------------------------------------------------------------

void check_message(const Case& c, const fs::path& dir, const Outcome& o, std::vector<Finding>& f) {
  const std::string error = first_line_starting(o.err, "error:");
  if (error.empty()) {
    f.push_back({"no-error-line", "exit " + std::to_string(o.code) +
                                      " without a line starting with \"error:\" on "
                                      "stderr; last stderr line: \"" +
                                      last_line(o.err) + "\""});
  }
  // The name checks read the error line, or all of stderr when there is none.
  const std::string message = error.empty() ? o.err : error;
  // (Plain searches: std::regex recurses per character and overflows the stack on long stderr.)
  static const char* library_texts[] = {
      "std::", "bad_alloc",   "basic_string", "vector::",     "map::at", "stod", "stoi",
      "stol",  "bad_variant", "bad_optional", "bad_function", "what()",  "_M_"};
  for (const char* t : library_texts) {
    if (message.find(t) != std::string::npos) {
      f.push_back({"message-library-text",
                   "the message is a C++ library's text: \"" + message.substr(0, 300) + "\""});
      break;
    }
  }
  // A number of 30 or more digits that soilsph wrote (one the user typed and the message quotes is
  // not counted here), e.g. 1.8e308 printed in full.
  std::size_t digits = 0, longest = 0, longest_end = 0;
  for (std::size_t k = 0; k < message.size(); ++k) {
    digits = message[k] >= '0' && message[k] <= '9' ? digits + 1 : 0;
    if (digits > longest) longest = digits, longest_end = k + 1;
  }
  if (longest >= 30) {
    const std::string run = message.substr(longest_end - longest, 30);
    bool typed = false;
    for (const File& file : c.files) typed = typed || file.content.find(run) != std::string::npos;
    for (const std::string& a : c.args) typed = typed || a.find(run) != std::string::npos;
    if (!typed)
      f.push_back({"message-long-number", "the message holds a number of " + std::to_string(longest) +
                                              " digits: \"" + message.substr(0, 300) + "\""});
  }
  if (!error.empty() && error.size() > 1000)
    f.push_back({"message-too-long", "the error line has " + std::to_string(error.size()) +
                                         " characters: \"" + error.substr(0, 200) + "...\""});
  const auto check_groups = [&](const std::vector<NameGroup>& groups) {
    for (const NameGroup& g : groups) {
      bool found = false;
      for (const std::string& s : g.any_of) found = found || message.find(s) != std::string::npos;
      if (!found) {
        std::string names;
        for (const std::string& s : g.any_of) names += (names.empty() ? "" : " or ") + s;
        f.push_back({"message-missing-name", "exit " + std::to_string(o.code) + " message does not name " +
                                                 g.what + " (" + names + "): \"" + last_line(message) +
                                                 "\""});
      }
    }
  };
  if (o.code == 2) check_groups(c.names_if_input);
  check_groups(c.names_if_failed);
  // A point run's failure names the integrator that ran (--integrator, else the material's), not another.
  if (c.command == "point" && o.code == 1) {
    std::string ran = material_integrator(c, dir);
    for (std::size_t k = 0; k + 1 < c.args.size(); ++k)
      if (c.args[k] == "--integrator") ran = c.args[k + 1];
    bool other = false;
    for (const char* name : {"explicit", "substep", "implicit"})
      other = other || (ran != name && message.find(name) != std::string::npos);
    if (other && (ran == "explicit" || ran == "substep" || ran == "implicit") &&
        message.find(ran) == std::string::npos)
      f.push_back({"message-wrong-integrator", "--integrator " + ran + " ran, the message names another: \"" +
                                                   last_line(message) + "\""});
  }
}

// ---------------------------------------------------------------------------------------------------
// soilsph material: the derived constants it prints must be finite, and positive where they must be.

void check_material_output(const Outcome& o, std::vector<Finding>& f) {
  // "NAME = NUMBER" pairs, e.g. "  K = 833333 Pa, G = 384615 Pa", "  M = 1.41833 (eq 26), ...".
  std::map<std::string, double> values;
  for (const std::string& line : lines_of(o.out)) {
    for (std::size_t at = line.find(" = "); at != std::string::npos; at = line.find(" = ", at + 3)) {
      std::size_t b = line.rfind(' ', at - 1);
      b = b == std::string::npos ? 0 : b + 1;
      const std::string name = line.substr(b, at - b);
      const char* start = line.c_str() + at + 3;
      char* end = nullptr;
      const double x = std::strtod(start, &end);
      if (end == start) {
        f.push_back({"material-output", name + " is not a number: \"" + line + "\""});
        continue;
      }
      values[name] = x;
    }
    if (const std::size_t d = line.find(", density "); d != std::string::npos)
      values["density"] = std::strtod(line.c_str() + d + 10, nullptr);
  }
  if (values.empty()) {
    f.push_back({"material-output", "no constants printed: \"" + last_line(o.out) + "\""});
    return;
  }
  for (const auto& [name, x] : values) {
    if (!std::isfinite(x)) f.push_back({"material-output", name + " = " + fmt(x) + " is not finite"});
  }
  for (const char* name : {"K", "G", "M", "(1+e0)/(lambda-kappa)", "alpha_phi", "density"}) {
    const auto it = values.find(name);
    if (it != values.end() && std::isfinite(it->second) && !(it->second > 0))
      f.push_back({"material-output", std::string(name) + " = " + fmt(it->second) + " is not positive"});
  }
  if (const auto it = values.find("k_c"); it != values.end() && it->second < 0)
    f.push_back({"material-output", "k_c = " + fmt(it->second) + " is negative"});
}

// ---------------------------------------------------------------------------------------------------
// soilsph point: the CSV (header comment, column names, one row per increment plus the start), all
// numbers finite, and what the test imposes: the start at p_initial, p = (sig_a + 2 sig_r)/3, and
// the drained radial stress, the undrained volume and total radial stress, the oedometer's radial
// strain, the isotropic deviator; the stress inside the yield surface.

void check_point_output(const Case& c, const fs::path& dir, const Outcome& o, std::vector<Finding>& f) {
  std::vector<std::string> lines = lines_of(o.out);
  // The conventions line, then any provenance comments (version, command, material, test), then
  // the column names: keep the first comment and drop the others.
  while (lines.size() > 2 && lines[1].starts_with("#")) lines.erase(lines.begin() + 1);
  if (lines.size() < 2 || !lines[0].starts_with("# soilsph point") ||
      lines[1] != "eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u,tau_xy,gamma_xy") {
    f.push_back({"point-output", "stdout is not the point CSV (comment, then eps_a,...,u): \"" +
                                     (lines.empty() ? std::string() : lines[0].substr(0, 80)) + "\""});
    return;
  }
  enum { eps_a, eps_r, eps_v, eps_q, sig_a, sig_r, p, q, p_c, u, tau_xy, gamma_xy, kColumns };
  static const char* names[] = {"eps_a", "eps_r", "eps_v", "eps_q", "sig_a",  "sig_r",
                                "p",     "q",     "p_c",   "u",     "tau_xy", "gamma_xy"};
  std::vector<std::array<double, kColumns>> rows;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    std::array<double, kColumns> r{};
    std::stringstream s(lines[i]);
    std::string cell;
    int k = 0;
    bool ok = true;
    for (; std::getline(s, cell, ','); ++k) {
      const std::optional<double> x = to_number(cell);
      if (k >= kColumns || !x) {
        ok = false;
        break;
      }
      r[k] = *x;
    }
    if (!ok || k != kColumns) {
      f.push_back({"point-output", "row " + std::to_string(i - 1) + " is not " + std::to_string(kColumns) +
                                       " numbers: \"" + lines[i] + "\""});
      return;
    }
    for (int j = 0; j < 10; ++j) {
      if (!std::isfinite(r[j])) {
        f.push_back({"point-output", "row " + std::to_string(i - 1) + ": " + names[j] + " = " + fmt(r[j]) +
                                         " (exit 0 with a non-finite result)"});
        return;
      }
    }
    rows.push_back(r);
  }
  if (c.kind == "programme") return;  // its legs and start are the file's: shape and finite values only
  const long long expected_rows =
      c.test == "strain-path" ? (c.strain_rows >= 0 ? c.strain_rows + 1 : -1) : c.increments * c.legs + 1;
  if (expected_rows >= 0 && static_cast<long long>(rows.size()) != expected_rows) {
    f.push_back(
        {"point-output", std::to_string(rows.size()) + " rows, expected " + std::to_string(expected_rows)});
    return;
  }
  if (rows.empty()) return;

  const std::optional<toml::table> doc = effective_toml(c, dir);
  const std::string model = doc ? str(*doc, "material", "model", "") : "";
  const double p0 = c.p_initial;
  const auto bad = [&](std::size_t i, const std::string& what) {
    f.push_back({"point-output", "row " + std::to_string(i + 1) + ": " + what});
  };
  // The start.
  const auto& r0 = rows.front();
  const double tol0 = 1e-9 * std::abs(p0);
  if (std::abs(r0[p] - p0) > tol0 || std::abs(r0[sig_a] - p0) > tol0 || std::abs(r0[sig_r] - p0) > tol0 ||
      std::abs(r0[q]) > tol0)
    bad(0, "the start is not p = sig_a = sig_r = p_initial = " + fmt(p0) + ", q = 0 (p = " + fmt(r0[p]) +
               ", q = " + fmt(r0[q]) + ")");
  if (model == "modified-cam-clay" && std::abs(r0[p_c] - c.ocr * p0) > 1e-9 * c.ocr * p0)
    bad(0, "p_c = " + fmt(r0[p_c]) + " is not OCR * p_initial = " + fmt(c.ocr * p0));
  const bool axisymmetric = c.test != "strain-path";
  // Model constants for the yield checks (plane-strain D-P of eq 19, MCC's M of eq 26).
  const double phi = doc ? num(*doc, "material", "friction_angle", NAN) : NAN;
  const double deg = std::numbers::pi / 180.0;
  const double tan_phi = std::tan(phi * deg), sin_phi = std::sin(phi * deg);
  const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);
  const double alpha = tan_phi / root;
  const double k_c = doc ? 3.0 * num(*doc, "material", "cohesion", 0.0) / root : NAN;
  const double M = 6.0 * sin_phi / (3.0 - sin_phi);
  const double psi = doc ? num(*doc, "material", "dilatancy_angle", 0.0) : NAN;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const double scale = std::max({std::abs(r[sig_a]), std::abs(r[sig_r]), std::abs(r[p]), std::abs(p0)});
    if (std::abs(r[p] - (r[sig_a] + 2 * r[sig_r]) / 3) > 1e-9 * scale && axisymmetric)
      return bad(i,
                 "p = " + fmt(r[p]) + " is not (sig_a + 2 sig_r)/3 = " + fmt((r[sig_a] + 2 * r[sig_r]) / 3));
    if (axisymmetric && std::abs(r[q] - (r[sig_a] - r[sig_r])) > 1e-9 * scale)
      return bad(i, "q = " + fmt(r[q]) + " is not sig_a - sig_r = " + fmt(r[sig_a] - r[sig_r]));
    if (c.test == "triaxial-drained" && std::abs(r[sig_r] - p0) > 1e-6 * scale)
      return bad(i, "drained triaxial: sig_r = " + fmt(r[sig_r]) + " is not p_initial = " + fmt(p0));
    if (c.test == "triaxial-undrained") {
      if (std::abs(r[eps_v]) > 1e-9 * std::max(1.0, std::abs(r[eps_a])))
        return bad(i, "undrained triaxial: eps_v = " + fmt(r[eps_v]) + " is not 0");
      if (std::abs(r[sig_r] + r[u] - p0) > 1e-6 * std::max(scale, std::abs(r[u])))
        return bad(i, "undrained triaxial: total radial stress sig_r + u = " + fmt(r[sig_r] + r[u]) +
                          " is not p_initial = " + fmt(p0));
      // Without dilatancy D-P (and linear elasticity) has no plastic volume change: undrained, p' stays.
      if ((model == "linear-elastic" || (model == "drucker-prager" && psi == 0.0)) &&
          std::abs(r[p] - p0) > 1e-6 * scale)
        return bad(i, "undrained triaxial of " + model + " without dilatancy: p' = " + fmt(r[p]) +
                          " is not p_initial = " + fmt(p0) + " (no plastic volume change)");
    }
    if (c.test == "oedometer" && std::abs(r[eps_r]) > 1e-12)
      return bad(i, "oedometer: eps_r = " + fmt(r[eps_r]) + " is not 0");
    if (c.test == "isotropic" &&
        (std::abs(r[sig_a] - r[sig_r]) > 1e-9 * scale || std::abs(r[q]) > 1e-9 * scale))
      return bad(i,
                 "isotropic: sig_a = " + fmt(r[sig_a]) + ", sig_r = " + fmt(r[sig_r]) + ", q = " + fmt(r[q]));
    if (model == "modified-cam-clay" && std::isfinite(M)) {
      if (!(r[p_c] > 0)) return bad(i, "MCC p_c = " + fmt(r[p_c]) + " is not positive");
      // On or inside the ellipse 0 <= p <= p_c whatever M (a friction angle of 1e-299 makes M^2 = 0).
      if (r[p] > r[p_c] * (1 + 1e-3) + 1e-6 * std::abs(p0) || r[p] < -1e-6 * std::abs(p0))
        return bad(i, "MCC p = " + fmt(r[p]) + " outside 0 <= p <= p_c = " + fmt(r[p_c]));
      // f = q^2 + M^2 p (p - p_c) <= 0, relative to its terms' size and to no less than 1e-3 p_initial
      // (the cvode reference drifts by 1e-3 near zero stress).
      const double floor = std::max(r[p_c], 1e-3 * std::abs(p0));
      const double yield = (r[q] * r[q] + M * M * r[p] * (r[p] - r[p_c])) /
                           (r[q] * r[q] + M * M * floor * floor + 1e-12 * p0 * p0);
      if (yield > 1e-3)
        return bad(i, "MCC stress outside the yield surface: f/(q^2 + M^2 p_c^2) = " + fmt(yield) +
                          " (p = " + fmt(r[p]) + ", q = " + fmt(r[q]) + ", p_c = " + fmt(r[p_c]) +
                          ", M = " + fmt(M) + ")");
    }
    if (model == "drucker-prager" && std::isfinite(alpha) && std::isfinite(k_c)) {
      const double limit = std::sqrt(3.0) * (3.0 * alpha * r[p] + k_c);
      if (std::abs(r[q]) > limit + 1e-3 * scale)
        return bad(i,
                   "D-P stress outside the yield surface: |q| = " + fmt(std::abs(r[q])) + " > " + fmt(limit));
    }
  }
  if (c.ocr_given && c.ocr != 1.0 && model != "modified-cam-clay" && o.err.find("ocr") == std::string::npos)
    f.push_back(
        {"ocr-ignored", "--ocr " + fmt(c.ocr) + " on " + model + " (no p_c) ran without a word on stderr"});
}

// ---------------------------------------------------------------------------------------------------
// soilsph collapse: summary.json complete and finite, the run reached its end (or rest), the frames
// written, and nothing flew: speeds within what the fall can give, the wall guard's corrections told.

std::map<std::string, std::string> flat_json(const std::string& text) {
  std::map<std::string, std::string> values;
  std::size_t at = 0;
  while ((at = text.find('"', at)) != std::string::npos) {
    const std::size_t key_end = text.find('"', at + 1);
    if (key_end == std::string::npos) break;
    const std::string key = text.substr(at + 1, key_end - at - 1);
    std::size_t colon = text.find_first_not_of(" \t\r\n", key_end + 1);
    if (colon == std::string::npos || text[colon] != ':') {
      at = key_end + 1;
      continue;
    }
    std::size_t v = text.find_first_not_of(" \t\r\n", colon + 1);
    if (v == std::string::npos) break;
    if (text[v] == '{' || text[v] == '[') {  // nested (initial_stress): its members are read as keys
      at = v + 1;
      continue;
    }
    std::size_t end;
    if (text[v] == '"') {
      end = v + 1;
      while (end < text.size() && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
      values[key] = text.substr(v, end + 1 - v);
      end += 1;
    } else {
      end = text.find_first_of(",}\n", v);
      values[key] = text.substr(v, end - v);
    }
    at = end;
  }
  return values;
}

void check_collapse_output(const Case& c, const fs::path& dir, const Outcome& o, std::vector<Finding>& f) {
  const fs::path out = fs::path(c.out_dir).is_absolute() ? fs::path(c.out_dir) : dir / c.out_dir;
  std::ifstream in(out / "summary.json");
  if (!in) {
    f.push_back({"collapse-output", "exit 0 without " + (out / "summary.json").string()});
    return;
  }
  std::stringstream s;
  s << in.rdbuf();
  // The figures are flat; the nested "materials" list and "inputs" object (the scene as run) come
  // last and are left out.
  const std::string text = s.str();
  const std::map<std::string, std::string> j =
      flat_json(text.substr(0, std::min(text.find("\"materials\":"), text.find("\"inputs\":"))));
  const auto number = [&](const std::string& key) -> std::optional<double> {
    const auto it = j.find(key);
    if (it == j.end()) return std::nullopt;
    return to_number(it->second);
  };
  const std::optional<toml::table> doc = effective_toml(c, dir);
  // The deposit measures are null (undefined) exactly for a scene of regions without [deposit]: no
  // frame to measure them from.
  const bool deposit_undefined =
      doc && !(*doc)["scene"]["column_width"] && !(*doc)["scene"]["column_height"] && !(*doc)["deposit"];
  const auto deposit_measure = [](const std::string& key) {
    return key == "runout_m" || key == "runout_thick_m" || key == "height_m" || key == "repose_angle_deg";
  };
  for (const auto& [key, value] : j) {
    const bool may_be_null = key == "resumed_from"  // null there means "not resumed"
                             || (deposit_undefined && deposit_measure(key));
    if (value == "null" && !may_be_null)
      f.push_back({"collapse-output", "summary.json " + key + " is null (not finite)"});
    if (value.front() != '"' && value != "true" && value != "false" && value != "null" && !to_number(value))
      f.push_back({"collapse-output", "summary.json " + key + " = " + value + " is not a number"});
    if (const std::optional<double> x = to_number(value); x && !std::isfinite(*x))
      f.push_back({"collapse-output", "summary.json " + key + " = " + value + " is not finite"});
  }
  if (const auto it = j.find("complete"); it != j.end() && it->second != "true")
    f.push_back({"collapse-output", "exit 0 with summary.json complete = " + it->second});
  for (const char* file : {"frames.h5", "frames.xdmf"})
    if (!fs::exists(out / file)) f.push_back({"collapse-output", std::string("exit 0 without ") + file});
  const std::optional<double> steps = number("steps"), dt = number("time_step"),
                              end_time = number("end_time");
  if (!steps || !(*steps >= 1))
    f.push_back({"collapse-output", "exit 0 after " + (steps ? fmt(*steps) : "?") + " steps (time_step = " +
                                        (dt                     ? fmt(*dt)
                                         : j.count("time_step") ? j.at("time_step")
                                                                : "?") +
                                        " s)"});
  if (!dt || !(*dt > 0) || !std::isfinite(*dt))
    f.push_back({"collapse-output", "time_step = " + (j.count("time_step") ? j.at("time_step") : "?")});
  if (doc) {
    const double scene_end = num(*doc, "scene", "end_time", NAN);
    const bool at_rest = j.count("stopped_at_rest") && j.at("stopped_at_rest") == "true";
    if (end_time && std::isfinite(scene_end) && !at_rest && *end_time < scene_end * (1 - 1e-9))
      f.push_back({"collapse-output", "exit 0 at t = " + fmt(*end_time) + " s, short of end_time = " +
                                          fmt(scene_end) + " s and not at rest"});
    // Nothing can move faster than a fall from the top of the column (3x margin, 0.5 m/s for waves).
    const double g = num(*doc, "scene", "gravity", NAN), H = num(*doc, "scene", "column_height", NAN);
    const double bound = 3.0 * std::sqrt(2.0 * g * H) + 0.5;
    if (const auto v = number("max_speed_end"); v && std::isfinite(bound) && *v > bound)
      f.push_back({"collapse-blowup", "exit 0 with max_speed_end = " + fmt(*v) + " m/s > " + fmt(bound) +
                                          " m/s (3 sqrt(2 g H) + 0.5)"});
    const double spacing = num(*doc, "scene", "particle_spacing", 0.0);
    if (const auto h = number("height_m"); h && std::isfinite(H) && *h > 1.5 * H + 2 * spacing)
      f.push_back({"collapse-blowup", "exit 0 with deposit height " + fmt(*h) +
                                          " m > 1.5 column_height = " + fmt(1.5 * H) + " m"});
  }
  if (const auto guard = number("guard_corrections"); guard && *guard > 0) {
    bool warned = false;
    for (const std::string& line : lines_of(o.err))
      warned = warned || (line.starts_with("warning:") && line.find("guard") != std::string::npos);
    if (!warned)
      f.push_back({"collapse-blowup", "exit 0 with the wall guard acting " + fmt(*guard) +
                                          " times and no warning: line on stderr"});
  }
}

}  // namespace

std::vector<Finding> check(const Case& c, const Outcome& o, const fs::path& dir) {
  std::vector<Finding> f;
  switch (o.status) {
    case Outcome::Status::NotStarted:
      f.push_back({"harness", "the child could not be started"});
      return f;
    case Outcome::Status::Hang:
      f.push_back({"hang", "no exit within " + fmt(o.seconds) + " s (killed); last stdout line: \"" +
                               last_line(o.out) + "\", last stderr line: \"" + last_line(o.err) + "\""});
      return f;
    case Outcome::Status::Signalled:
      f.push_back({"signal", std::string("killed by signal ") + std::to_string(o.code) + " (" +
                                 strsignal(o.code) + "); last stderr line: \"" + last_line(o.err) + "\""});
      return f;
    case Outcome::Status::Exited:
      break;
  }
  if (o.code < 0 || o.code > 2)
    f.push_back({"exit-status", "exit status " + std::to_string(o.code) + " (not 0, 1 or 2)"});
  if (o.err.find("HDF5-DIAG") != std::string::npos)
    f.push_back({"library-diagnostics", "HDF5's diagnostics on stderr"});
  if (o.code != 0) {
    check_message(c, dir, o, f);
    if (c.expect == Expect::InputError && o.code == 1)
      f.push_back({"input-error-exit-1", "exit 1 for an input error (" + c.expect_why + "), expected 2"});
    // The default K0 must be admissible for every valid material. (When the change of another
    // key, e.g. gravity = 1e308, is blamed on K0, that is message-missing-name, not this.)
    bool blamed_elsewhere = false;
    for (const Finding& g : f) blamed_elsewhere = blamed_elsewhere || g.category == "message-missing-name";
    // Only the error line: a `note:` may rightly say which K0 the default became. And only [initial]'s
    // key: with the [initial] header deleted, "[scene] lateral_stress_ratio: is not a known key" is right.
    if (o.code == 2 && !blamed_elsewhere &&
        last_line(o.err).find("[initial] lateral_stress_ratio") != std::string::npos) {
      const std::optional<toml::table> doc = effective_toml(c, dir);
      if (doc && !(*doc)["initial"]["lateral_stress_ratio"].node())
        f.push_back({"default-k0-rejected", "the default K0 (no lateral_stress_ratio given) is refused: \"" +
                                                last_line(o.err) + "\""});
    }
    return f;
  }
  if (c.expect != Expect::Any)
    f.push_back({"bad-input-accepted", "exit 0, expected " +
                                           std::string(c.expect == Expect::InputError ? "2" : "1 or 2") +
                                           " (" + c.expect_why + ")"});
  // The output checks assume the inputs as documented; an accepted bad input is reported above.
  if (c.expect != Expect::Any) return f;
  if (c.command == "material") check_material_output(o, f);
  if (c.command == "point") check_point_output(c, dir, o, f);
  if (c.command == "collapse") check_collapse_output(c, dir, o, f);
  return f;
}

}  // namespace soilsph::fuzz
