#include "constitutive/models/linear_elastic.h"

namespace soilsph {

LinearElasticParams LinearElasticParams::read(const TableReader& t) {
  LinearElasticParams p{};
  p.density = t.number("density", Range::positive(), "kg/m^3");
  p.young_modulus = t.number("young_modulus", Range::positive(), "Pa");
  p.poisson_ratio = t.number("poisson_ratio", Range::open(-1.0, 0.5));
  return p;
}

}  // namespace soilsph
