#pragma once
/// @file
/// The initial configuration of a collapse: the soil lattice, the ghost-particle walls and floor,
/// and the geostatic stress that holds the column in equilibrium before the wall moves.
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/stages/boundaries.h"

namespace soilsph::sph {

/// The soil as an nx × ny lattice at spacing Δp from (0, 0) to (W, H) (41 × 61 at 1 mm for the paper's
/// 4 cm × 6 cm), mass ρ Δp² per unit thickness, at rest, layer ids from the bottom; then the boundary:
/// `boundary_layers` rows below the floor (y = −kΔp) from the far end of the floor to under the fixed
/// wall, as many columns right of the fixed wall (x = W + kΔp) and, with wall_withdrawal = "none",
/// left of the removable wall (x = −kΔp), up to H + 2h. "instant" removes that wall at t = 0, i.e.
/// the run starts without it while the stress is the one it held.
Particles build_particles(const Scene& scene);

/// Geostatic stress for every soil particle, tension-positive:
///   σyy = −ρ g (H + Δp/2 − y),   σxx = σzz = K0 σyy,   σxy = 0,
/// the weight of the soil above the top of the particle's own cell (the free surface lies half a
/// spacing above the top row). For MCC, p_c = max(OCR · p_c,yield, p_c,floor) with
/// p_c,yield = p + q²/(M² p), the p_c that puts (p, q) on the surface (eq 24): at the free surface
/// p → 0 and p_c,yield → 0, which would leave the top without any strength, so the floor
/// ([initial] preconsolidation_floor) bounds it. Throws ParameterError if a particle's initial
/// stress lies outside the yield surface (e.g. a K0 too far from 1 for D-P).
void set_geostatic_state(Particles& particles, const Scene& scene);

/// The smallest lateral stress ratio K0 (σxx/σyy = σzz/σyy) for which the geostatic stress of the
/// column lies inside the material's yield surface, found by bisection on the model's own yield
/// function at the column's base (the strictest depth: the D-P cone's distance grows with depth
/// at K0 below its bound, and cohesion only helps near the surface); 0 if every K0 > 0 is
/// admissible (elasticity, MCC, whose p_c is set from the stress). Above it every K0 up to 1 is
/// admissible: an isotropic stress lies inside a cone or an ellipse through the origin.
double smallest_admissible_lateral_stress_ratio(const Material& material, const Geometry& geometry);

/// The largest initial mean pressure p of the soil (Pa), for the elastic wave speed.
double largest_initial_pressure(const Scene& scene);

/// The wall surfaces, half a spacing in front of the first boundary layer.
WallGuard wall_guard(const Scene& scene);

}  // namespace soilsph::sph
