#include "constitutive/integrators/integrator.h"

#include <stdexcept>

namespace soilsph {

Integrator parse_integrator(std::string_view name) {
  for (Integrator scheme : kIntegrators)
    if (integrator_name(scheme) == name) return scheme;
  throw std::invalid_argument("unknown integrator \"" + std::string(name) + "\"");
}

}  // namespace soilsph
