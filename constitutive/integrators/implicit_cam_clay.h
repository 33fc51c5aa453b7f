#pragma once
/// @file
/// `implicit` for Modified Cam-Clay: closest-point projection (backward Euler) after Borja & Lee
/// (1990, Comput. Methods Appl. Mech. Eng. 78:49–72), with
///  - the hardening law exact in the increment: p_c = p_c,n exp(θ Δε_v^p), θ = (1+e0)/(λ−κ) (eq 27);
///  - the volumetric elasticity integrated exactly: p = P(p_n, Δε_v − Δε_v^p), i.e.
///    p = p_n exp(Δε_v^e/κ*) above the floor (Elasticity::pressure_after), so an isotropic path
///    follows the NCL and the swelling lines exactly;
///  - the shear modulus taken at the end of the step, G = G(p_{n+1}) (backward Euler on the
///    hypoelastic shear law s' = 2G(p) ė^e), so that s = (s_n + 2G Δe)/(1 + 6GΔλ).
/// Unknowns: the plastic volumetric strain v = Δε_v^p (compression-positive) and Δλ. Residuals:
///   r1 = v − Δλ M²(2p − p_c)  (the flow rule's volumetric part),  r2 = f(p, q, p_c) (eq 24).
/// For a given Δλ, r1 is strictly increasing in v and bracketed, so v(Δλ) is found by safeguarded
/// Newton; the outer equation f(Δλ) = 0 is solved by safeguarded Newton with its exact derivative,
/// bracketed by f(0) > 0 and f → −M²p² < 0 as Δλ → ∞. Non-convergence throws IntegrationError.
/// The consistent tangent follows from the implicit-function theorem on (r1, r2): see
/// docs/integrators.md.
#include "constitutive/models/modified_cam_clay.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// One implicit update (no spin); writes the consistent tangent ∂σ/∂Δε when `tangent` is not null.
State implicit_update(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr);

}  // namespace soilsph
