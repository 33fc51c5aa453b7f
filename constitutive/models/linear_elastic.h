#pragma once
/// @file
/// Linear isotropic elasticity (Hooke's law, eq 14): the baseline every plastic model reduces to
/// inside its yield surface.
#include "constitutive/elasticity.h"
#include "constitutive/parameters.h"
#include "constitutive/rotation.h"

namespace soilsph {

struct LinearElasticParams {
  double density;        ///< kg/m³
  double young_modulus;  ///< Pa
  double poisson_ratio;  ///< −

  static LinearElasticParams read(const TableReader& table);
};

class LinearElastic {
 public:
  using Params = LinearElasticParams;
  static constexpr std::string_view kName = "linear-elastic";

  explicit LinearElastic(const Params& params)
      : params_(params), elasticity_(Elasticity::constant(params.young_modulus, params.poisson_ratio)) {}

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }

  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment) const {
    State next = rotate_state(state, spin_increment);
    next.stress += elasticity_.at(0.0).stiffness(strain_increment);
    next.plastic_multiplier = 0.0;
    return next;
  }

 private:
  Params params_;
  Elasticity elasticity_;
};

}  // namespace soilsph
