#pragma once
/// @file
/// Names of the stress-integration schemes. A model stores the scheme chosen from its input once;
/// its update switches on this enum (a predictable branch, no virtual call).
#include <stdexcept>
#include <string>
#include <string_view>

namespace soilsph {

enum class Integrator {
  Explicit,  ///< the paper's explicit rate form (eq 16, 21–22, 28–29) with stress correction (eq 30–35)
  Substep,   ///< modified-Euler substepping with local error control (Sloan, Abbo & Sheng 2001)
  Implicit,  ///< return mapping with the consistent tangent: D-P closest-point projection, MCC generalised midpoint
};

/// The input/CLI name of a scheme, e.g. "explicit".
std::string_view integrator_name(Integrator integrator);
/// All scheme names accepted in input files, for messages and validation.
inline constexpr std::string_view kIntegratorNames[] = {"explicit", "substep", "implicit"};
/// The scheme for a name; throws std::invalid_argument for an unknown name.
Integrator parse_integrator(std::string_view name);

/// Default relative stress-error tolerance of `substep` (material key `substep_tolerance`).
inline constexpr double kDefaultSubstepTolerance = 1e-6;

class TableReader;
/// Reads the optional `integrator` key of a material table; `fallback` when absent (each model's
/// default is the scheme with the best accuracy for its cost in docs/integrators.md).
Integrator read_integrator(const TableReader& table, Integrator fallback);
/// Reads the optional `substep_tolerance` key (default kDefaultSubstepTolerance, 1e-12 ≤ value ≤ 1e-2).
double read_substep_tolerance(const TableReader& table);

/// A stress update that cannot be completed (no convergence, inadmissible state): never a NaN.
class IntegrationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace soilsph
