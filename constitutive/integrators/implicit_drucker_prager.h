#pragma once
/// @file
/// `implicit` for Drucker–Prager: closest-point projection (backward Euler) in closed form.
/// With constant elasticity and the potential g = √J2 + α_ψ I1 (eq 20 with α_ψ = 3 sinψ, or the
/// matched α_ψ: DruckerPrager::alpha_psi()), the return σ = σ_tr − Δλ D : n_g(σ) keeps the deviator's
/// direction (n_g's deviatoric part is s/(2√J2) and s ∥ s_tr), so
///   √J2 = √J2_tr − G Δλ,   I1 = I1_tr − 9 K α_ψ Δλ,   Δλ = f_tr / (G + 9 α_φ α_ψ K)   (cone)
/// which puts σ exactly on the cone f = 0. The cone return is admissible while √J2 ≥ 0, i.e.
/// √J2_tr ≥ G Δλ; otherwise the trial lies past the apex (for ψ = 0 exactly where I1_tr > k_c/α_φ) and
/// the state returns to the apex I1 = k_c/α_φ, s = 0 (the paper's tension cut-off, eq 30–31).
/// Derivation and tangent: docs/method/integrators.md.
#include "constitutive/models/drucker_prager.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// One implicit update (no spin); writes the consistent tangent ∂σ/∂Δε when `tangent` is not null.
State implicit_update(const DruckerPrager& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr);

}  // namespace soilsph
