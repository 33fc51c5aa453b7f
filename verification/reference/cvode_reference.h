#pragma once
/// @file
/// The reference solution of a material-point test: the continuum elastic–plastic rate equations
///   σ̇ = D^ep : ε̇,   D^ep = D − (D:n_g) ⊗ (n_f:D) / (n_f:D:n_g + H),
///   ṗ_c = hardening_rate(σ, p_c, λ̇, n_g),   ε̇^p = λ̇ n_g,  λ̇ = n_f:D:ε̇ / (n_f:D:n_g + H)
/// (MCC eq 27–29, ṗ_c = (1+e0)/(λ−κ) · p_c · (−tr ε̇^p); D-P eq 21–22 with H = 0 and ṗ_c = 0; any
/// model through its PlasticModel hooks; D = elasticity().at(p), the tangent moduli) integrated
/// with SUNDIALS CVODE (BDF, dense Newton, rtol 1e-12: about 1e-10 relative global error on the
/// MCC triaxial paths, 1e-8 with rtol 1e-10) under the same mixed control as the
/// driver: at every right-hand-side evaluation the free strain rates are solved from the imposed
/// stress rates with the current D^ep. Pseudo-time is the increment count of a leg, so the output
/// falls on the driver's increments. The elastic→plastic transition (f = 0) and elastic unloading
/// (λ̇ = 0) are located by CVODE's root finding; the integration is reinitialised there with the
/// other branch, so the kink is resolved and never stepped across. A model made of planes
/// (Mohr–Coulomb's `planes()`) flows on each plane the stress lies on with its own multiplier,
/// the active set chosen by Koiter's rule (yield_surfaces.h), and each plane has its own switching
/// function. Only the model's pure functions (yield, yield_gradient, flow_direction, planes,
/// hardening_modulus, hardening_rate, elasticity) are used, not its update.
#include <span>

#include "constitutive/material.h"
#include "verification/driver/point_history.h"
#include "verification/paths/load_path.h"

namespace soilsph::verification {

struct CvodeOptions {
  double relative_tolerance = 1e-12;
  /// Absolute tolerances: stresses and p_c get this times the initial stress scale (max |σ|, p_c),
  /// strains get it as is.
  double absolute_tolerance = 1e-14;
  /// A state counts as on the yield surface at the start of a leg when normalized_yield ≥ −this.
  double surface_tolerance = 1e-8;
  long max_steps_per_increment = 100000;
};

/// Integrates every leg from `initial`: one sample per increment, the initial state first.
/// Throws IncrementError with CVODE's message when the integration fails.
PointHistory cvode_reference(const Material& material, const State& initial, std::span<const Leg> legs,
                             const CvodeOptions& options = {});

}  // namespace soilsph::verification
