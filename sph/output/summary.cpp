// summary.json written by hand (output/json_text.h); the nested "inputs" object is
// toml++'s JSON rendering of the scene as run.
#include "sph/output/summary.h"

#include "sph/output/atomic_file.h"
#include "sph/output/json_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace soilsph::sph {
namespace {

/// A nested JSON text indented one level further (it follows a key of the top-level object).
std::string indented(const std::string& json) {
  std::string out;
  for (const char c : json) out += c == '\n' ? std::string("\n  ") : std::string(1, c);
  return out;
}

/// The walls as a JSON array: name, kind, points, and when present the time it is removed and its
/// velocity with the interval it moves in.
std::string boundaries_json(const std::vector<Wall>& walls) {
  static constexpr const char* kKinds[] = {"free-slip", "no-slip", "frictional"};
  const auto pair = [](Vec2 v) { return "[" + number(v.x) + ", " + number(v.y) + "]"; };
  std::string out = "[";
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const Wall& w = walls[k];
    out += k ? ",\n    {" : "\n    {";
    out += quoted("name") + ": " + quoted(w.label) + ", " + quoted("kind") + ": " +
           quoted(w.symmetry_plane ? "symmetry" : kKinds[static_cast<int>(w.kind)]) + ", " + quoted("points") + ": [";
    for (std::size_t i = 0; i < w.points.size(); ++i) {
      if (i) out += ", ";
      out += pair(w.points[i]);
    }
    out += "]";
    if (std::isfinite(w.motion.removed_at)) out += ", " + quoted("removed_at") + ": " + number(w.motion.removed_at);
    if (w.motion.moves())
      out += ", " + quoted("velocity") + ": " + pair(w.motion.velocity) + ", " + quoted("start") + ": " +
             number(w.motion.start) + ", " + quoted("end") + ": " + number(w.motion.end);
    out += "}";
  }
  return out + (walls.empty() ? "]" : "\n  ]");
}

}  // namespace

std::string InitialStressRecord::json() const {
  if (method == "flat-surface") return "";
  std::string o = "{\"method\": " + quoted(method);
  if (relaxation_steps >= 0)
    o += ", \"steps\": " + std::to_string(relaxation_steps) +
         ", \"kinetic_energy\": " + number(relaxation_kinetic_energy) +
         ", \"stress_change\": " + number(relaxation_stress_change);
  return o + "}";
}

std::string summary_json(const Summary& s) {
  std::string out = "{\n";
  bool first = true;
  const auto field = [&](const char* key, const std::string& value) {
    out += first ? "  " : ",\n  ";
    first = false;
    out += quoted(key) + ": " + value;
  };
  field("model", quoted(s.model));
  field("integrator", quoted(s.integrator));
  field("particles", std::to_string(s.particles));
  field("boundary_particles", std::to_string(s.boundary_particles));
  field("steps", std::to_string(s.steps));
  field("threads", std::to_string(s.threads));
  field("end_time", number(s.end_time));
  field("wall_seconds", number(s.wall_seconds));
  field("particle_steps_per_second", number(s.particle_steps_per_second));
  field("runout_m", number(s.runout_m));
  field("height_m", number(s.height_m));
  field("repose_angle_deg", number(s.repose_angle_deg));
  field("runout_thick_m", number(s.runout_thick_m));
  field("max_speed_end", number(s.max_speed_end));
  field("kinetic_energy_end", number(s.kinetic_energy_end));
  field("particle_spacing", number(s.particle_spacing));
  field("smoothing_ratio", number(s.smoothing_ratio));
  field("time_step", number(s.time_step));
  field("smallest_time_step", number(s.smallest_time_step));
  field("largest_time_step", number(s.largest_time_step));
  field("stopped_at_rest", s.stopped_at_rest ? "true" : "false");
  field("guard_corrections", std::to_string(s.guard_corrections));
  field("fallback_stress_updates", std::to_string(s.fallback_stress_updates));
  field("complete", s.complete ? "true" : "false");
  field("stop_reason", quoted(s.stop_reason));
  field("resumed_from", s.resumed_from >= 0 ? number(s.resumed_from) : "null");
  if (const std::string initial_stress = s.initial_stress.json(); !initial_stress.empty())
    field("initial_stress", initial_stress);
  field("version", quoted(s.version));
  field("command_line", quoted(s.command_line));
  std::string materials = "[";
  for (std::size_t k = 0; k < s.materials.size(); ++k)
    materials += std::string(k ? ",\n    " : "\n    ") + "{\"name\": " + quoted(s.materials[k].name) + ", \"model\": " +
                 quoted(s.materials[k].model) + ", \"integrator\": " + quoted(s.materials[k].integrator) +
                 ", \"particles\": " + std::to_string(s.materials[k].particles) + "}";
  field("materials", materials + (s.materials.empty() ? "]" : "\n  ]"));
  if (!s.inputs_json.empty()) field("inputs", indented(s.inputs_json));
  // Nested values come last, after the flat figures (readers that scan the figures stop at "inputs").
  if (!s.boundaries.empty()) field("boundaries", boundaries_json(s.boundaries));
  return out + "\n}\n";
}

void write_summary_json(const std::filesystem::path& file, const Summary& summary) {
  replace_file(file, summary_json(summary));
}

}  // namespace soilsph::sph
