#pragma once
/// @file
/// Why a collapse of a model's soil may loosen without bound and never come to rest, as advice that
/// names the key to set. Two mechanisms, both the models' own and measured in docs/validation/collapse.md:
///  - a constant ψ > 0 without `dilatancy_cutoff` dilates as long as the soil shears;
///  - a tension cut-off below the pyramid's apex c cot φ (Mohr–Coulomb with c > 0) opens tension
///    cracks whose associated flow is opening without resistance; without an internal length they are
///    one particle wide, the face peels off in single-particle slabs and their grains scatter.
#include <sstream>
#include <string>

#include "constitutive/models/dilatancy_cutoff.h"

namespace soilsph {

/// "" for a soil that can rest; otherwise why it may not, with the key to set.
template <class Model>
std::string unbounded_loosening(const Model& model) {
  std::ostringstream why;
  if (dilates_without_bound(model))
    why << "its dilatancy_angle > 0 without a [material] dilatancy_cutoff dilates without bound as it shears "
           "(set one such as 0.05, docs/validation/collapse.md)";
  if constexpr (requires { model.has_tension_cutoff(); }) {
    if (model.has_tension_cutoff())
      why << (why.tellp() > 0 ? "; and " : "") << "its tension_cutoff (" << model.tension_cutoff()
          << " Pa) below the apex c cot(phi) = " << model.apex_stress()
          << " Pa opens tension cracks one particle wide, whose grains scatter (a larger tension_cutoff, or "
             "none, docs/validation/collapse.md)";
  }
  return why.str();
}

}  // namespace soilsph
