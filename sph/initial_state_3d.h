#pragma once
/// @file
/// The initial configuration of a 3D scene (sph/scene_3d.h): the soil on its lattice, the ghost
/// particles behind its planar walls and the geostatic stress, as the 2D initial_state.h builds
/// them in the plane.
#include "constitutive/material.h"
#include "sph/particles.h"
#include "sph/scene_3d.h"
#include "sph/stages/wall_motions.h"

namespace soilsph::sph {

/// The soil on the lattice nodes inside the scene's solid (geometry/solid.h), in its order (k, j,
/// i), mass ρ Δp³, at rest, material 0, layer ids along −g from the bottom of the lowest particle's
/// cell by [output] layer_thickness; then the ghosts of every wall, boundary_layers deep
/// (geometry/planar_ghosts.h), each with its wall's inward normal, friction μ (0 free slip, +∞ no
/// slip, tan δ), id and kind, with the soil's density and mass, and the velocity of its wall at
/// t = 0. The stress is zero: see set_geostatic_state_3d.
ParticlesOf<3> build_particles_3d(const Scene3& scene);

/// The motions of the scene's walls, by wall index (stages/wall_motions.h).
WallMotionsOf<3> wall_motions(const Scene3& scene);

/// The geostatic stress of space, tension-positive: σ = σ_v (K0 (I − ĝĝ) + ĝĝ) with
/// σ_v = −ρ |g| (surface − height), the weight of the soil above along −g and K0 σ_v on every
/// horizontal axis, no shear in the gravity frame; with gravity along −y: σyy = σ_v,
/// σxx = σzz = K0 σ_v, no shear, exactly.
Mat3 geostatic_stress_3d(const Geometry3& g, double density, double k0, double surface, double height);

/// Every soil particle's stress and hardening state below the flat free surface
/// Geometry3::surface_level (the column's H0, the slab's H0 + Δp/2), as set_geostatic_state does in 2D (MCC's
/// p_c likewise); the stress copied into sxx, syy, szz, sxy, sxz, syz. Throws ParameterError if a particle's
/// stress lies outside the yield surface.
void set_geostatic_state_3d(ParticlesOf<3>& particles, const Scene3& scene);

/// The scene's particles as a collapse starts from them, before any gravity-loading relaxation:
/// built (build_particles_3d) and in their geostatic state (set_geostatic_state_3d).
ParticlesOf<3> geostatic_particles(const Scene3& scene);

/// The smallest K0 for which the geostatic stress at the soil's base lies inside the material's
/// yield surface (geostatic_state.h); 0 if every K0 > 0 is.
double smallest_admissible_lateral_stress_ratio_3d(const Material& material, const Geometry3& geometry);

/// The largest initial mean pressure p of the soil (Pa): at its base.
double largest_initial_pressure(const Scene3& scene);

}  // namespace soilsph::sph
