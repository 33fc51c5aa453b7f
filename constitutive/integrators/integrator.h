#pragma once
/// @file
/// Names of the stress-integration schemes. A model stores the scheme chosen from its input once;
/// its update switches on this enum (a predictable branch, no virtual call).
#include <string>
#include <string_view>

namespace soilsph {

enum class Integrator {
  Explicit,  ///< the paper's explicit rate form (eq 16, 21–22, 28–29) with stress correction (eq 30–35)
};

/// The input/CLI name of a scheme, e.g. "explicit".
std::string_view integrator_name(Integrator integrator);
/// All scheme names accepted in input files, for messages and validation.
inline constexpr std::string_view kIntegratorNames[] = {"explicit"};
/// The scheme for a name; throws std::invalid_argument for an unknown name.
Integrator parse_integrator(std::string_view name);

class TableReader;
/// Reads the optional `integrator` key of a material table (default "explicit").
Integrator read_integrator(const TableReader& table);

}  // namespace soilsph
