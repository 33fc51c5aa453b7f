#include "constitutive/models/linear_elastic.h"

#include "constitutive/material_limits.h"

namespace soilsph {

LinearElasticParams LinearElasticParams::read(const TableReader& t) {
  LinearElasticParams p{};
  p.density = t.number("density", Range::positive(), "kg/m^3");
  p.young_modulus = t.number("young_modulus", limits::young_modulus_range(), "Pa");
  p.poisson_ratio = t.number("poisson_ratio", Range::open(-1.0, 0.5));
  return p;
}

}  // namespace soilsph
