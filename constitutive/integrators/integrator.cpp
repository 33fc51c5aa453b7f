#include "constitutive/integrators/integrator.h"

#include <stdexcept>

#include "constitutive/parameters.h"

namespace soilsph {

std::string_view integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::Explicit: return "explicit";
    case Integrator::Substep: return "substep";
    case Integrator::Implicit: return "implicit";
  }
  return "unknown";
}

Integrator parse_integrator(std::string_view name) {
  if (name == "explicit") return Integrator::Explicit;
  if (name == "substep") return Integrator::Substep;
  if (name == "implicit") return Integrator::Implicit;
  throw std::invalid_argument("unknown integrator \"" + std::string(name) + "\"");
}

Integrator read_integrator(const TableReader& table, Integrator fallback) {
  return parse_integrator(table.choice_or("integrator", integrator_name(fallback), kIntegratorNames));
}

double read_substep_tolerance(const TableReader& table) {
  return table.number_or("substep_tolerance", kDefaultSubstepTolerance, Range::closed(1e-12, 1e-2));
}

}  // namespace soilsph
