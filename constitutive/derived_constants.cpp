#include "constitutive/derived_constants.h"

#include <cmath>

namespace soilsph {

void require_derived(std::string_view owner, std::string_view key, double value, std::string_view formula,
                     double constant, std::string_view unit, bool zero_allowed) {
  const bool ok = std::isfinite(constant) && (zero_allowed ? constant >= 0.0 : constant > 0.0);
  if (ok) return;
  throw DerivedConstantError(owner, key, value,
                             "gives " + std::string(formula) + " = " + format_number(constant) +
                                 (unit.empty() ? "" : " ") + std::string(unit) + ", which must be finite and " +
                                 (zero_allowed ? ">= 0" : "> 0"));
}

void require_constant_moduli(std::string_view owner, double young_modulus, const Elasticity& elasticity) {
  const Moduli D = elasticity.at(0.0);
  require_derived(owner, "young_modulus", young_modulus, "K = E/(3(1-2 nu))", D.K, "Pa");
  require_derived(owner, "young_modulus", young_modulus, "G = E/(2(1+nu))", D.G, "Pa");
}

}  // namespace soilsph
