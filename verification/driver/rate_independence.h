#pragma once
/// @file
/// The material-point driver integrates strain increments without a time, so a material's
/// viscoplastic relaxation time (constitutive/viscoplastic_relaxation.h), which needs one, does not
/// apply there: said on stderr rather than dropped silently.
#include <iostream>
#include <string_view>

#include "constitutive/material.h"

namespace soilsph {

inline void warn_if_rate_dependent(const Material& material, std::string_view source) {
  if (viscoplastic_relaxation_time(material) > 0.0)
    std::cerr << "warning: " << source
              << ": [material] viscoplastic_relaxation_time is ignored here: the material-point driver "
                 "is rate-independent (the key acts in soilsph collapse)\n";
}

}  // namespace soilsph
