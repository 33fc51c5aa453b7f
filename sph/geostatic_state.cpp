#include "sph/geostatic_state.h"

#include <sstream>

namespace soilsph::sph {

std::string inadmissible_geostatic_message(const std::string& source, const std::string& position,
                                           const std::string& table, double k0) {
  std::ostringstream msg;
  msg << source << ": the geostatic stress at " << position << " m lies outside the yield surface of "
      << table << "; K0 = " << k0 << " ([initial] lateral_stress_ratio) is not admissible for it";
  return msg.str();
}

double smallest_admissible_lateral_stress_ratio(
    const Material& material, const std::function<Mat3(double density, double k0)>& base_stress) {
  return std::visit(
      [&](const auto& model) {
        const auto admissible = [&](double k0) {
          State s;
          s.stress = base_stress(model.params().density, k0);
          s.pc =
              initial_preconsolidation(model, s.stress, {k0, 1.0, 0.0, {}, InitialStress::FlatSurface, {}});
          return admissible_state(model, s);
        };
        double lo = 0.0, hi = 1.0;  // inadmissible at lo (or lo = 0), admissible at hi
        if (admissible(1e-12)) return 0.0;
        for (int k = 0; k < 60 && hi - lo > 1e-12; ++k)
          (admissible(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
        return hi;
      },
      material);
}

}  // namespace soilsph::sph
