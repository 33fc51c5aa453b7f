#include "constitutive/models/linear_elastic.h"

#include <sstream>

#include "constitutive/derived_constants.h"
#include "constitutive/material_limits.h"

namespace soilsph {

template <class Io>
void LinearElasticParams::fields(const Io& io) {
  io.number("density", density, Range::positive(), "kg/m^3");
  io.number("young_modulus", young_modulus, limits::young_modulus_range(), "Pa");
  io.number("poisson_ratio", poisson_ratio, Range::open(-1.0, 0.5));
}
template void LinearElasticParams::fields(const FieldChecker&);
template void LinearElasticParams::fields(const FieldDescriber&);
template void LinearElasticParams::fields(const KeyLister&);

LinearElastic::LinearElastic(const Params& params)
    : params_(validated(params, kName)),
      elasticity_(Elasticity::constant(params.young_modulus, params.poisson_ratio)) {
  require_constant_moduli(kName, params.young_modulus, elasticity_);
}

std::string LinearElastic::describe_constants() const {
  const Moduli D = elasticity_.at(0.0);
  std::ostringstream out;
  out << "  K = " << D.K << " Pa, G = " << D.G << " Pa\n";
  return out.str();
}

LinearElasticParams LinearElasticParams::read(const TableReader& t) {
  return read_fields<LinearElasticParams>(t);
}

}  // namespace soilsph
