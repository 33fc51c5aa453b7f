#pragma once
/// @file
/// `implicit` for Modified Cam-Clay: a return mapping after Borja & Lee (1990, Comput. Methods Appl.
/// Mech. Eng. 78:49–72) with the flow rule integrated by the generalised midpoint rule (Ortiz & Popov
/// 1985, Int. J. Numer. Methods Eng. 21:1561–1576), material key `implicit_alpha`:
///  - α = 1 is backward Euler (closest-point projection), first order;
///  - α = ½ (the default) is second order: 20 increments reach 1e-5 (drained) and 1e-4 (undrained)
///    on the Table 1 triaxial paths to ε_a = 0.1 (constant E = 1 MPa), where backward Euler has 3e-3
///    and 7e-3; a stiffer clay (K = (1+e0)p/κ from 200 kPa) needs `implicit_tolerance` (below);
///  - the flow of an increment that starts inside the surface is taken from its elastic entry to
///    the surface σ_t (found by Newton on the exact elastic path), not from σ_n;
///  - a stiffness cap on the entry's weight keeps large softening steps from overshooting (see
///    CamClayReturn in the .cpp and docs/method/integrators.md).
/// In every variant:
///  - the hardening law is exact in the increment: p_c = p_c,n exp(θ Δε_v^p), θ = (1+e0)/(λ−κ) (eq 27);
///  - the volumetric elasticity is integrated exactly: p = P(p_n, Δε_v − Δε_v^p), i.e.
///    p = p_n exp(Δε_v^e/κ*) above the floor (Elasticity::pressure_after), so an isotropic path
///    follows the NCL and the swelling lines exactly;
///  - the shear modulus is the secant one over the elastic volume change, G = G_sec(p_n, Δε_v^e), so a
///    purely elastic increment of the hypoelastic law s' = 2G(p) ė^e is exact for a proportional
///    strain increment.
/// Unknowns: the plastic volumetric strain v = Δε_v^p (compression-positive) and Δλ; residuals: the
/// flow rule's volumetric part r1(v, Δλ) = 0 and the yield condition f(p, q, p_c) = 0 (eq 24). For a
/// given Δλ, v(Δλ) is found by safeguarded Newton in a bracket; the outer equation f(Δλ) = 0 by
/// safeguarded Newton with its exact derivative, from f(0) > 0. Before that, plain Newton on both
/// unknowns together (one evaluation per iteration instead of an inner solve per outer one) is tried
/// from the first-order estimate at the entry or, for an increment whose plastic shear dwarfs the
/// elastic one (a dust particle at the free surface), from the stress kept at the entry, and kept
/// when it converges inside v's bracket; in the SPH collapse one of the two starts does for every
/// return (the first for all but ~1e-5 of them), and the update costs 1.4–1.9× less
/// (docs/method/integrators.md).
/// Non-convergence throws IntegrationError.
/// The consistent tangent follows from the implicit-function theorem on (r1, f), including how the
/// entry σ_t moves with Δε: see docs/method/integrators.md.
#include "constitutive/models/modified_cam_clay.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// What the error-controlled update below learns from one return besides its result.
struct ReturnEstimate {
  double euler = 0.0;             ///< the Euler difference R (0 for an elastic step)
  double elastic_fraction = 0.0;  ///< t* of a start strictly inside that reaches the surface, else 0
  State entry;                    ///< the exact elastic state at t* (when elastic_fraction > 0)
};

/// One return over the whole increment (no spin); writes the consistent tangent ∂σ/∂Δε when `tangent`
/// is not null, and what the error-controlled update needs when `estimate` is not null.
State implicit_return(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr, ReturnEstimate* estimate = nullptr);

/// The `implicit` update (no spin). With `implicit_tolerance` = 0 (the default) one implicit_return.
/// Otherwise error-controlled sub-incrementation: a sub-increment is accepted when the Euler
/// difference R = ½Δλ‖D:(n(σ_{n+1}) − n(σ_t))‖ (relative to the stress; Sloan, Abbo & Sheng 2001's
/// estimate with implicit stages, pessimistic for the midpoint) is ≤ implicit_tolerance, or else when
/// the step-doubling estimate ‖X(h) − X(h/2 + h/2)‖/3 of the midpoint's own O(h³) local error is;
/// then the local extrapolation of the two halves is kept (O(h⁴), back on the surface by the drift
/// correction). The elastic part of an increment that reaches the surface from inside is taken
/// exactly, and only the rest is controlled. An increment that needs no split costs one return, as
/// without control. The tangent is the analytic one of the single return over the whole increment
/// (exact when the increment is not split, an approximation for the driver's Newton otherwise).
/// Measured against CVODE and `substep`: docs/method/integrators.md.
State implicit_update(const ModifiedCamClay& model, const State& start, const Mat3& strain_increment,
                      Mat6* tangent = nullptr);

}  // namespace soilsph
