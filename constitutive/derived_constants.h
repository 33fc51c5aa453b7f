#pragma once
/// @file
/// The constants a model derives from its keys (moduli, α_φ, k_c, M, the hardening exponent) must be
/// finite and positive: in-range keys can still combine into an overflow (e0 = 1e308 makes
/// (1+e0)/(λ−κ) infinite) or an underflow (E = 5e-324 makes G = 0), which would turn every stress
/// into inf or NaN. Each model's constructor checks its own constants with these helpers, so a
/// model built in code is refused like one read from a file; read_material rethrows the error
/// through its TableReader, so that the message also names the file.
#include <string>
#include <string_view>

#include "constitutive/elasticity.h"
#include "constitutive/parameters.h"

namespace soilsph {

/// A derived constant that is not finite and positive, blaming the key `key` (value `value`).
class DerivedConstantError : public ParameterError {
 public:
  DerivedConstantError(std::string_view owner, std::string_view key, double value, std::string reason)
      : ParameterError(std::string(owner) + " parameters: " + std::string(key) + " = " + format_number(value) + " " + reason),
        key_(key), value_(value), reason_(std::move(reason)) {}
  const std::string& key() const { return key_; }
  double value() const { return value_; }
  /// "gives FORMULA = X UNIT, which must be finite and > 0".
  const std::string& reason() const { return reason_; }

 private:
  std::string key_;
  double value_;
  std::string reason_;
};

/// Throws DerivedConstantError unless `constant` (written as `formula`, in `unit`) is finite and > 0
/// (≥ 0 with `zero_allowed`: k_c of a cohesionless soil); `owner` is the model's name.
void require_derived(std::string_view owner, std::string_view key, double value, std::string_view formula,
                     double constant, std::string_view unit, bool zero_allowed = false);

/// K and G of constant elasticity, blaming young_modulus.
void require_constant_moduli(std::string_view owner, double young_modulus, const Elasticity& elasticity);

}  // namespace soilsph
