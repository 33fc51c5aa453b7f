#pragma once
/// @file
/// `implicit` for Drucker–Prager: closest-point projection (backward Euler) in closed form.
/// With constant elasticity and the potential g = √J2 + 3 I1 sinψ (eq 20), the return
/// σ = σ_tr − Δλ D : n_g(σ) keeps the deviator's direction (n_g's deviatoric part is s/(2√J2) and
/// s ∥ s_tr), so
///   √J2 = √J2_tr − G Δλ,   I1 = I1_tr − 27 K sinψ Δλ,   Δλ = f_tr / (G + 27 α_φ K sinψ)   (cone)
/// which puts σ exactly on the cone f = 0. The cone return is admissible while √J2 ≥ 0, i.e.
/// √J2_tr ≥ G Δλ; otherwise the trial lies past the apex (for ψ = 0 exactly where I1_tr > k_c/α_φ) and
/// the state returns to the apex I1 = k_c/α_φ, s = 0 (the paper's tension cut-off, eq 30–31).
/// Derivation and tangent: docs/integrators.md.
#include "constitutive/models/drucker_prager.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// One implicit update (no spin); writes the consistent tangent ∂σ/∂Δε when `tangent` is not null.
State implicit_update(const DruckerPrager& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr);

}  // namespace soilsph
