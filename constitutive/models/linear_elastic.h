#pragma once
/// @file
/// Linear isotropic elasticity (Hooke's law, eq 14): the baseline every plastic model reduces to
/// inside its yield surface.
#include <string>

#include "constitutive/elasticity.h"
#include "constitutive/models/perfect_plasticity.h"
#include "constitutive/parameters.h"
#include "constitutive/rotation.h"

namespace soilsph {

struct LinearElasticParams {
  double density = 0.0;        ///< kg/m³ (required)
  double young_modulus = 0.0;  ///< Pa (required)
  double poisson_ratio = 0.0;  ///< − (required)

  static LinearElasticParams read(const TableReader& table);
  /// Every key with its range, read, checked, described or listed by `io`
  /// (FieldReader, FieldChecker, FieldDescriber, KeyLister), in the order results list them.
  template <class Io>
  void fields(const Io& io);
};

class LinearElastic : public NoHardeningVariable {
 public:
  using Params = LinearElasticParams;
  static constexpr std::string_view kName = "linear-elastic";

  explicit LinearElastic(const Params& params);

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }
  /// The derived constants, one "  name = value" line each (`soilsph material`).
  std::string describe_constants() const;

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
