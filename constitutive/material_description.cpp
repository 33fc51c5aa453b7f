#include "constitutive/material_description.h"

#include <charconv>

namespace soilsph {

namespace {
using Parameters = std::vector<std::pair<std::string, std::string>>;

std::string number(double x) {
  return exact_number(x);
}
std::string quoted(std::string_view text) {
  return "\"" + std::string(text) + "\"";
}

void add_common(Parameters& out, std::string_view model, double density) {
  out.emplace_back("model", quoted(model));
  out.emplace_back("density", number(density));
}

Parameters parameters(const LinearElastic& m) {
  Parameters out;
  add_common(out, LinearElastic::kName, m.params().density);
  out.emplace_back("young_modulus", number(m.params().young_modulus));
  out.emplace_back("poisson_ratio", number(m.params().poisson_ratio));
  return out;
}

void add_relaxation_time(Parameters& out, double tau) {
  if (tau > 0.0) out.emplace_back("viscoplastic_relaxation_time", number(tau));  // absent: rate-independent
}

/// The keys of frictional_fields (D-P, Mohr–Coulomb), after model and density.
template <class Model>
Parameters frictional_parameters(const Model& m) {
  const auto& p = m.params();
  Parameters out;
  add_common(out, Model::kName, p.density);
  out.emplace_back("young_modulus", number(p.young_modulus));
  out.emplace_back("poisson_ratio", number(p.poisson_ratio));
  out.emplace_back("friction_angle", number(p.friction_angle));
  out.emplace_back("cohesion", number(p.cohesion));
  out.emplace_back("dilatancy_angle", number(p.dilatancy_angle));
  add_relaxation_time(out, p.viscoplastic_relaxation_time);
  return out;
}

Parameters parameters(const DruckerPrager& m) {
  const auto& p = m.params();
  Parameters out = frictional_parameters(m);
  out.emplace_back("plastic_potential", quoted(plastic_potential_name(p.plastic_potential)));
  out.emplace_back("integrator", quoted(integrator_name(p.integrator)));
  out.emplace_back("substep_tolerance", number(p.substep_tolerance));
  return out;
}

Parameters parameters(const ModifiedCamClay& m) {
  const auto& p = m.params();
  const bool constant = p.elasticity == Elasticity::Kind::Constant;
  Parameters out;
  add_common(out, ModifiedCamClay::kName, p.density);
  if (constant) out.emplace_back("young_modulus", number(p.young_modulus));
  out.emplace_back("poisson_ratio", number(p.poisson_ratio));
  out.emplace_back("friction_angle", number(p.friction_angle));
  out.emplace_back("compression_index", number(p.compression_index));
  out.emplace_back("swelling_index", number(p.swelling_index));
  out.emplace_back("initial_void_ratio", number(p.initial_void_ratio));
  out.emplace_back("elasticity", quoted(name_of(kElasticityKindTable, p.elasticity)));
  if (!constant) out.emplace_back("elastic_pressure_floor", number(p.elastic_pressure_floor));
  out.emplace_back("integrator", quoted(integrator_name(p.integrator)));
  out.emplace_back("substep_tolerance", number(p.substep_tolerance));
  out.emplace_back("implicit_alpha", number(p.implicit_alpha));
  out.emplace_back("implicit_tolerance", number(p.implicit_tolerance));
  if (p.minimum_preconsolidation > 0.0)  // absent: none
    out.emplace_back("minimum_preconsolidation", number(p.minimum_preconsolidation));
  if (p.hardening_volume == HardeningVolume::Current)  // absent: "initial"
    out.emplace_back("hardening_volume", quoted(name_of(kHardeningVolumeTable, p.hardening_volume)));
  add_relaxation_time(out, p.viscoplastic_relaxation_time);
  return out;
}
Parameters parameters(const MohrCoulomb& m) {
  const auto& p = m.params();
  Parameters out = frictional_parameters(m);
  out.emplace_back("integrator", quoted(integrator_name(p.integrator)));
  out.emplace_back("substep_tolerance", number(p.substep_tolerance));
  if (p.tension_cutoff != MohrCoulomb::Params::kNoTensionCutoff)  // absent: none
    out.emplace_back("tension_cutoff", number(p.tension_cutoff));
  return out;
}
std::string numbers(const std::vector<double>& values) {
  std::string list;
  for (const double v : values) list += (list.empty() ? "" : ", ") + number(v);
  return "[" + list + "]";
}
Parameters parameters(const UmatModel& m) {
  const auto& p = m.params();
  Parameters out;
  add_common(out, UmatModel::kName, p.density);
  out.emplace_back("library", quoted(p.library));
  out.emplace_back("symbol", quoted(p.symbol));
  out.emplace_back("name", quoted(p.name));
  out.emplace_back("props", numbers(p.props));
  out.emplace_back("state_variables", std::to_string(p.state_variables));
  if (!p.initial_state.empty()) out.emplace_back("initial_state", numbers(p.initial_state));
  out.emplace_back("stress_unit", quoted(name_of(kStressUnitTable, p.stress_unit)));
  out.emplace_back("thread_safe", p.thread_safe ? "true" : "false");
  return out;
}
}  // namespace

std::string exact_number(double x) {
  // Plain digits where they are short (100000, not 1e+05), else the shortest form.
  char buffer[400];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed);
  if (result.ec == std::errc() && result.ptr - buffer <= 12) return std::string(buffer, result.ptr);
  result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

std::vector<std::pair<std::string, std::string>> material_parameters(const Material& material) {
  return std::visit([](const auto& model) { return parameters(model); }, material);
}

std::string describe_material(const Material& material) {
  std::string line;
  for (const auto& [key, value] : material_parameters(material))
    line += (line.empty() ? "" : "; ") + key + " = " + value;
  return line;
}

}  // namespace soilsph
