#include "constitutive/integrators/integrator.h"

#include <stdexcept>

namespace soilsph {

Integrator parse_integrator(std::string_view name) {
  if (const std::optional<Integrator> scheme = parse_name(kIntegratorTable, name)) return *scheme;
  throw std::invalid_argument("unknown integrator \"" + std::string(name) + "\"");
}

}  // namespace soilsph
