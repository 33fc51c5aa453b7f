#include "constitutive/derived_constants.h"

#include <cmath>

namespace soilsph {

namespace {
/// `constant` (written as `formula`, in `unit`) must be finite and > 0; else the key `key`, whose
/// value is `value`, is blamed. `zero_allowed`: ≥ 0 instead (k_c of a cohesionless soil).
void require(const TableReader& t, std::string_view key, double value, std::string_view formula,
             double constant, std::string_view unit, bool zero_allowed = false) {
  const bool ok = std::isfinite(constant) && (zero_allowed ? constant >= 0.0 : constant > 0.0);
  if (ok) return;
  t.fail_value(key, format_number(value),
               "gives " + std::string(formula) + " = " + format_number(constant) + (unit.empty() ? "" : " ") +
                   std::string(unit) + ", which must be finite and " + (zero_allowed ? ">= 0" : "> 0"));
}

/// K and G of constant elasticity, from E and ν.
void check_constant_elasticity(const TableReader& t, double young_modulus, const Elasticity& e) {
  const Moduli D = e.at(0.0);
  require(t, "young_modulus", young_modulus, "K = E/(3(1-2 nu))", D.K, "Pa");
  require(t, "young_modulus", young_modulus, "G = E/(2(1+nu))", D.G, "Pa");
}

void check(const LinearElastic& m, const TableReader& t) {
  check_constant_elasticity(t, m.params().young_modulus, m.elasticity());
}

void check(const DruckerPrager& m, const TableReader& t) {
  const auto& p = m.params();
  check_constant_elasticity(t, p.young_modulus, m.elasticity());
  require(t, "friction_angle", p.friction_angle, "alpha_phi = tan(phi)/sqrt(9 + 12 tan^2(phi)) (eq 19)",
          m.alpha_phi(), "");
  require(t, "cohesion", p.cohesion, "k_c = 3c/sqrt(9 + 12 tan^2(phi)) (eq 19)", m.k_c(), "Pa", true);
  // The apex I1 = k_c/α_φ, where tension is cut off (eq 30–31); 3c/tan φ, so a small φ overflows it.
  require(t, "cohesion", p.cohesion, "the apex's I1 = 3c/tan(phi)", m.apex_first_invariant(), "Pa", true);
}

void check(const MohrCoulomb& m, const TableReader& t) {
  const auto& p = m.params();
  check_constant_elasticity(t, p.young_modulus, m.elasticity());
  require(t, "friction_angle", p.friction_angle, "sin(phi)", m.sin_phi(), "");
  // The apex c cot(phi), where the pyramid closes; a small φ overflows it.
  require(t, "cohesion", p.cohesion, "the apex's principal stress c cot(phi)", m.apex_stress(), "Pa", true);
}

void check(const ModifiedCamClay& m, const TableReader& t) {
  const auto& p = m.params();
  require(t, "friction_angle", p.friction_angle, "M = 6 sin(phi)/(3 - sin(phi)) (eq 26)", m.M(), "");
  require(t, "initial_void_ratio", p.initial_void_ratio, "(1+e0)/(lambda-kappa) (eq 27)",
          m.hardening_exponent(), "");
  if (p.elasticity == Elasticity::Kind::Constant) {
    check_constant_elasticity(t, p.young_modulus, m.elasticity());
    return;
  }
  // The smallest pressure-dependent moduli, at the floor: K = p_floor (1+e0)/κ.
  const Moduli D = m.elasticity().at(0.0);
  require(t, "elastic_pressure_floor", p.elastic_pressure_floor, "K = p_floor (1+e0)/kappa", D.K, "Pa");
  require(t, "elastic_pressure_floor", p.elastic_pressure_floor, "G = 3K(1-2 nu)/(2(1+nu))", D.G, "Pa");
}
}  // namespace

void check_derived_constants(const Material& material, const TableReader& table) {
  std::visit([&table](const auto& model) { check(model, table); }, material);
}

}  // namespace soilsph
