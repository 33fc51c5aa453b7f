#pragma once
/// @file
/// Names of the stress-integration schemes. A model stores the scheme chosen from its input once;
/// its update switches on this enum (a predictable branch, no virtual call).
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>

#include "constitutive/enum_names.h"
#include "constitutive/parameters.h"

namespace soilsph {

enum class Integrator {
  Explicit,  ///< the paper's explicit rate form (eq 16, 21–22, 28–29) with stress correction (eq 30–35)
  Substep,   ///< modified-Euler substepping with local error control (Sloan, Abbo & Sheng 2001)
  Implicit,  ///< return mapping with the consistent tangent: D-P closest-point projection, MCC generalised
             ///< midpoint
};

/// Every scheme with its input/CLI name, in the order of the enum: the one table that the parser, the
/// messages, the stress test and the benchmarks read (a new scheme is added here and in the enum only).
inline constexpr auto kIntegratorTable = enum_table<Integrator>({
    {Integrator::Explicit, "explicit"},
    {Integrator::Substep, "substep"},
    {Integrator::Implicit, "implicit"},
});
/// The schemes and their names, in table order.
inline constexpr auto kIntegrators = values_of(kIntegratorTable);
inline constexpr auto kIntegratorNames = names_of(kIntegratorTable);

/// The input/CLI name of a scheme, e.g. "explicit".
constexpr std::string_view integrator_name(Integrator integrator) {
  return name_of(kIntegratorTable, integrator);
}
/// The scheme for a name; throws std::invalid_argument for an unknown name.
Integrator parse_integrator(std::string_view name);

/// Default relative stress-error tolerance of `substep` (material key `substep_tolerance`).
inline constexpr double kDefaultSubstepTolerance = 1e-6;
/// Allowed `substep_tolerance`: 1e-12 ≤ value ≤ 1e-2.
inline constexpr Range kSubstepToleranceRange{1e-12, 1e-2, false, false};

/// A stress update that cannot be completed (no convergence, inadmissible state): never a NaN.
class IntegrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace soilsph
