#pragma once
/// @file
/// The initial configuration of a collapse: the soil lattice, the ghost-particle walls and floor,
/// and the geostatic stress that holds the column in equilibrium before the wall moves.
#include "sph/particles.h"
#include "sph/scene.h"
#include "sph/stages/boundaries.h"

namespace soilsph::sph {

/// The soil on the lattice inside the layout's regions (geometry/lattice.h; the column: an nx × ny
/// lattice from (0, 0) to (W, H), 41 × 61 at 1 mm for the paper's 4 cm × 6 cm), mass ρ Δp² per unit
/// thickness, at rest, layer ids from the bottom along −g; then the ghost rows of every wall present
/// at t = 0 (a wall removed at 0, the column's "instant" withdrawal, is never built: the run starts
/// without it while the stress is the one it held), each with its wall's normal, friction and velocity.
/// Several materials: the soil ordered by material (Scene::materials; the lattice order within
/// each), each particle with its material index and ρ Δp² of its own ρ; each ghost with the density
/// and mass of the soil particle nearest to it.
Particles build_particles(const Scene& scene);

/// Copies the ghosts' wall normals (in space also the corner normals), friction and ids, which a
/// checkpoint does not hold, from `from` (the scene's particles as built) to `to` (a checkpoint's);
/// throws if the counts differ. In 2D and 3D (instantiated for both).
template <int dim>
void copy_wall_attributes(ParticlesOf<dim>& to, const ParticlesOf<dim>& from);

/// Geostatic stress for every soil particle, tension-positive, below the free surface that
/// [initial] stress chooses: "flat-surface", one level at the top of the soil's outline along −g
/// (the column: H + Δp/2, half a spacing above the top row), or "local-surface" (and the start of
/// "gravity-loading"), the top of the soil on the particle's vertical (geometry/surface.h):
///   σ_v = −ρ |g| (surface − height),   σ_h = σzz = K0 σ_v,   no shear in the gravity frame,
/// with gravity along −y σyy = σ_v, σxx = σzz = K0 σ_v, σxy = 0. For MCC, p_c = max(OCR · p_c,yield, p_c,floor) with
/// p_c,yield = p + q²/(M² p), the p_c that puts (p, q) on the surface (eq 24): at the free surface
/// p → 0 and p_c,yield → 0, which would leave the top without any strength, so the floor
/// ([initial] preconsolidation_floor) bounds it. Throws ParameterError if a particle's initial
/// stress lies outside the yield surface (e.g. a K0 too far from 1 for D-P). Several materials: each
/// particle's σ_v is the weight of its lattice column above it, each particle with its own density,
/// and σ_h uses its material's K0 (InitialConditions::material_lateral_stress_ratio).
void set_geostatic_state(Particles& particles, const Scene& scene);

/// The scene's particles as a collapse starts from them, before any gravity-loading relaxation:
/// built (build_particles) and in their geostatic state (set_geostatic_state).
Particles geostatic_particles(const Scene& scene);

/// The smallest lateral stress ratio K0 (σxx/σyy = σzz/σyy) for which the geostatic stress of the
/// column lies inside the material's yield surface, found by bisection on the model's own yield
/// function at the column's base (the strictest depth: the D-P cone's distance grows with depth
/// at K0 below its bound, and cohesion only helps near the surface); 0 if every K0 > 0 is
/// admissible (elasticity, MCC, whose p_c is set from the stress). Above it every K0 up to 1 is
/// admissible: an isotropic stress lies inside a cone or an ellipse through the origin.
double smallest_admissible_lateral_stress_ratio(const Material& material, const Geometry& geometry);

/// The largest initial mean pressure p of the soil (Pa), for the elastic wave speed (several
/// materials: an upper bound, with the heaviest density and the largest K0).
double largest_initial_pressure(const Scene& scene);

/// The wall guard of every wall surface present at t = 0.
WallGuard wall_guard(const Scene& scene);

/// The motions of the layout's walls, by wall index.
WallMotions wall_motions(const Scene& scene);

}  // namespace soilsph::sph
