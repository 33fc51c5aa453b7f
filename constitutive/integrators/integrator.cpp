#include "constitutive/integrators/integrator.h"

#include <stdexcept>

#include "constitutive/parameters.h"

namespace soilsph {

std::string_view integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::Explicit: return "explicit";
  }
  return "unknown";
}

Integrator parse_integrator(std::string_view name) {
  if (name == "explicit") return Integrator::Explicit;
  throw std::invalid_argument("unknown integrator \"" + std::string(name) + "\"");
}

Integrator read_integrator(const TableReader& table) {
  return parse_integrator(table.choice_or("integrator", "explicit", kIntegratorNames));
}

}  // namespace soilsph
