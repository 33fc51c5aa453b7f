#pragma once
/// @file
/// The particles as a structure of arrays, in 2 or 3 dimensions. Soil particles come first,
/// [0, soil_count); the fixed boundary (ghost) particles follow, [soil_count, size()). Every array
/// has size() entries except those marked soil only (soil_count entries) and boundary only
/// (boundary_count() entries).
///
/// The plane's arrays are those of ParticlesOf<2>; space adds the z components (ThirdAxisArrays<3>):
/// a 2D run has no z array at all, so its memory, checkpoints and loops are those of a plane-strain
/// code. Generic stages read the third axis under `if constexpr (dim == 3)`.
#include <array>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "constitutive/state.h"
#include "sph/geometry/layout.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// The kind of wall a boundary particle belongs to (geometry/layout.h); recorded for checkpoints and
/// output. The mirroring reads the ghost's friction coefficient instead (stages/boundaries.h).
using BoundaryKind = WallKind;

/// Components of a symmetric tensor of the dimension: 3 in the plane (xx, yy, xy), 6 in space.
template <int dim>
inline constexpr int kSymmetricComponents = dim == 2 ? 3 : 6;

/// Where component (a, b) of a symmetric tensor of the dimension is kept: the diagonal first, then
/// xy (plane); xy, xz, yz (space), as the particles' stress arrays are listed.
template <int dim>
constexpr int symmetric_index(int a, int b) {
  if (a == b) return a;
  if constexpr (dim == 2)
    return 2;
  else
    return a + b + 2;  // (0,1) → 3, (0,2) → 4, (1,2) → 5
}

/// What particle j contributes to every pair term of the momentum equation, packed so that a pair
/// reads one record of j instead of one line from each of many arrays: σ/ρ², v^{n−½}, ρ^n, m, and
/// whether j carries an artificial stress. Copied for every particle at the start of each step
/// (stages/momentum.h, set_momentum_source); valid until the step changes σ, v or ρ. 96 B in space;
/// in the plane 64 B (one cache line), with named scalars: GCC 12 vectorises the plane's row sum
/// across pairs for this record and across components for one of arrays, which sums in another
/// order and would change the plane's results in their last bits.
template <int dim>
struct MomentumSourceOf {
  std::array<double, kSymmetricComponents<dim>> stress_rho2;  ///< σ/ρ² (m²/s²), symmetric_index order
  std::array<double, dim> v;                                  ///< m/s
  double density, mass;
  bool tension;  ///< R ≠ 0 (stages/artificial_stress.h)
};
template <>
struct MomentumSourceOf<2> {
  double sxx_rho2, syy_rho2, sxy_rho2;  ///< σ/ρ² (m²/s²)
  double vx, vy;                        ///< m/s
  double density, mass;
  bool tension;  ///< R ≠ 0 (stages/artificial_stress.h)
};
static_assert(sizeof(MomentumSourceOf<2>) == 64 && sizeof(MomentumSourceOf<3>) == 96);
using MomentumSource = MomentumSourceOf<2>;

/// The arrays of the third axis: none in the plane.
template <int dim>
struct ThirdAxisArrays {};
template <>
struct ThirdAxisArrays<3> {
  std::vector<double> z, vz;            ///< every particle: position (m), velocity (m/s)
  std::vector<double> szz, sxz, syz;    ///< every particle: stress (Pa)
  std::vector<double> rzz, rxz, ryz;    ///< every particle: artificial stress / ρ² (m²/s²)
  std::vector<double> az;               ///< soil: acceleration (m/s²)
  std::vector<double> lxz, lyz, lzx, lzy, lzz;  ///< soil: velocity gradient ∂v^α/∂x^β (1/s)
  std::vector<double> z0;               ///< soil: position at t = 0 (m)
  std::vector<double> wall_nz, wall_vz;  ///< boundary: wall normal and velocity
  /// Boundary: ±1 per axis. A ghost's image across the further free-slip walls it also lies behind
  /// besides its own (the floor's edge below a free-slip side wall; not a symmetry plane, whose
  /// images its row holds): each such wall is normal to an axis (initial_state_3d.cpp), and its
  /// reflection flips that axis's component, so their product is a sign per axis; 1 where there is
  /// none. A mirror image's (stages/mirror_images.h): the reflection it carries. A vector's
  /// component a is multiplied by image_sign[a], a tensor's (a, b) by both.
  std::vector<double> image_sign_x, image_sign_y, image_sign_z;
};

template <int dim>
  requires(dim == 2 || dim == 3)
struct ParticlesOf : ThirdAxisArrays<dim> {
  static constexpr int dimension = dim;
  using Source = MomentumSourceOf<dim>;

  std::size_t soil_count = 0;  ///< soil particles are the first soil_count entries
  /// The boundary particles [soil_count, image_begin) are ghosts on the lattice behind the walls,
  /// fixed in number; [image_begin, size()) the soil's mirror images behind symmetry planes, rebuilt
  /// at each neighbour search (stages/mirror_images.h).
  std::size_t image_begin = 0;

  // Every particle (soil then boundary).
  std::vector<double> x, y;           ///< position (m)
  std::vector<double> vx, vy;         ///< velocity (m/s); at half steps for the soil (leapfrog)
  std::vector<double> density;        ///< kg/m³
  std::vector<double> mass;           ///< kg; per metre of thickness in the plane (plane strain)
  std::vector<double> sxx, syy, sxy;  ///< stress used by the momentum equation (Pa)
  std::vector<double> rxx, ryy, rxy;  ///< artificial stress (Gray et al. 2001), divided by ρ² (m²/s²)
  std::vector<Source> momentum_source;  ///< per step, for the pairs of the momentum equation

  // Soil only.
  std::vector<double> ax, ay;              ///< acceleration (m/s²)
  std::vector<double> density_rate;        ///< Dρ/Dt, eq 11 (kg/m³/s)
  std::vector<double> lxx, lxy, lyx, lyy;  ///< velocity gradient ∂v^α/∂x^β, eq 23 (1/s)
  std::vector<double> x0, y0;              ///< position at t = 0 (m), for displacements (gauges)
  std::vector<State> state;                ///< full 3×3 stress and hardening state
  std::vector<int> layer;                  ///< horizontal layer id from the bottom (for pictures)
  std::vector<int> material;               ///< index into Scene::materials; each material's particles are contiguous
  /// The particle's identity for as long as the run lasts, in frames, checkpoints, gauges and
  /// messages: its index as the scene built it. Today the arrays never reorder, so id[i] == i; a
  /// distributed run (docs/method/mpi-design.md) moves particles between ranks and indices, never ids.
  std::vector<std::uint64_t> id;

  // Boundary only, indexed by (i − soil_count): the wall each ghost mirrors across, chosen once
  // when the ghosts are built so that the step runs one formula for every kind (stages/boundaries.h).
  std::vector<BoundaryKind> boundary_kind;
  std::vector<double> wall_nx, wall_ny;  ///< unit wall normal towards the soil
  std::vector<double> wall_vx, wall_vy;  ///< the wall's velocity now (m/s)
  std::vector<double> wall_friction;     ///< μ = tan δ: 0 free slip, +∞ no slip
  std::vector<double> wall_stick;        ///< 1 if the wall holds the soil this step, 0 if it slides (set with the stress)
  std::vector<int> wall_id;              ///< index of its wall in the layout

  std::size_t size() const { return x.size(); }
  std::size_t boundary_count() const { return size() - soil_count; }
  std::size_t image_count() const { return size() - image_begin; }
  bool is_soil(std::size_t i) const { return i < soil_count; }

  /// The coordinate arrays (x, y[, z]), for the neighbour search.
  std::array<std::span<const double>, dim> coordinates() const {
    if constexpr (dim == 2)
      return {x, y};
    else
      return {x, y, this->z};
  }
  /// The coordinate arrays (x, y[, z]), for the step's drift.
  std::array<std::vector<double>*, dim> position_arrays() {
    if constexpr (dim == 2)
      return {&x, &y};
    else
      return {&x, &y, &this->z};
  }
  /// The velocity arrays (vx, vy[, vz]).
  std::array<std::vector<double>*, dim> velocity_arrays() {
    if constexpr (dim == 2)
      return {&vx, &vy};
    else
      return {&vx, &vy, &this->vz};
  }
  Vec<dim> position(std::size_t i) const {
    if constexpr (dim == 2)
      return {x[i], y[i]};
    else
      return {x[i], y[i], this->z[i]};
  }
  /// Soil particle i's position at t = 0 (x0, y0[, z0]).
  Vec<dim> start_position(std::size_t i) const {
    if constexpr (dim == 2)
      return {x0[i], y0[i]};
    else
      return {x0[i], y0[i], this->z0[i]};
  }
  Vec<dim> velocity(std::size_t i) const {
    if constexpr (dim == 2)
      return {vx[i], vy[i]};
    else
      return {vx[i], vy[i], this->vz[i]};
  }

  /// Calls f(name, array) for every array of doubles: first those of every particle, then those of
  /// the soil only (the one list that sizing, memory counts and checkpoints use).
  template <class F>
  void for_each_array(F&& f) {
    for_each_array_of(*this, f);
  }
  template <class F>
  void for_each_array(F&& f) const {
    for_each_array_of(*this, f);
  }
  /// The first arrays for_each_array visits (those of every particle).
  static constexpr std::size_t kParticleArrays = dim == 2 ? 12 : 20;

  /// Calls f(array) for every array of doubles of the boundary only.
  template <class F>
  void for_each_wall_array(F&& f) {
    for_each_wall_array_of(*this, f);
  }
  template <class F>
  void for_each_wall_array(F&& f) const {
    for_each_wall_array_of(*this, f);
  }

  /// Bytes held by the arrays.
  std::size_t bytes() const {
    std::size_t b = state.capacity() * sizeof(State) + momentum_source.capacity() * sizeof(Source) +
                    (layer.capacity() + material.capacity()) * sizeof(int) +
                    id.capacity() * sizeof(std::uint64_t) + boundary_kind.capacity() +
                    wall_id.capacity() * sizeof(int);
    for_each_wall_array([&](const std::vector<double>& a) { b += a.capacity() * sizeof(double); });
    for_each_array([&](const char*, const std::vector<double>& a) { b += a.capacity() * sizeof(double); });
    return b;
  }

  /// Sizes every array for `soil` soil and `boundary` boundary particles (zero-filled).
  void resize(std::size_t soil, std::size_t boundary) {
    soil_count = soil;
    std::size_t k = 0;
    for_each_array([&](const char*, std::vector<double>& a) { a.assign(k++ < kParticleArrays ? soil + boundary : soil, 0.0); });
    momentum_source.assign(soil + boundary, Source{});
    state.assign(soil, State{});
    layer.assign(soil, 0);
    material.assign(soil, 0);
    id.resize(soil);
    std::iota(id.begin(), id.end(), std::uint64_t{0});
    boundary_kind.assign(boundary, BoundaryKind::NoSlip);
    for_each_wall_array([&](std::vector<double>& a) { a.assign(boundary, 0.0); });
    if constexpr (dim == 3)  // no further plane behind a ghost until its builder finds one
      for (auto* sign : {&this->image_sign_x, &this->image_sign_y, &this->image_sign_z}) sign->assign(boundary, 1.0);
    wall_id.assign(boundary, 0);
    image_begin = soil + boundary;
  }

  /// Resizes the boundary to `boundary` particles, keeping the soil and the first boundary
  /// particles as they are (new entries zero); image_begin stays.
  void resize_boundary(std::size_t boundary) {
    const std::size_t n = soil_count + boundary;
    std::size_t k = 0;
    for_each_array([&](const char*, std::vector<double>& a) {
      if (k++ < kParticleArrays) a.resize(n, 0.0);
    });
    momentum_source.resize(n, Source{});
    boundary_kind.resize(boundary, BoundaryKind::FreeSlip);
    for_each_wall_array([&](std::vector<double>& a) { a.resize(boundary, 0.0); });
    wall_id.resize(boundary, 0);
  }

 private:
  template <class Self, class F>
  static void for_each_array_of(Self& p, F& f) {
    if constexpr (dim == 2) {
      f("x", p.x), f("y", p.y), f("vx", p.vx), f("vy", p.vy), f("density", p.density), f("mass", p.mass);
      f("sxx", p.sxx), f("syy", p.syy), f("sxy", p.sxy), f("rxx", p.rxx), f("ryy", p.ryy), f("rxy", p.rxy);
      f("ax", p.ax), f("ay", p.ay), f("density_rate", p.density_rate);
      f("lxx", p.lxx), f("lxy", p.lxy), f("lyx", p.lyx), f("lyy", p.lyy);
      f("x0", p.x0), f("y0", p.y0);
    } else {
      f("x", p.x), f("y", p.y), f("z", p.z), f("vx", p.vx), f("vy", p.vy), f("vz", p.vz);
      f("density", p.density), f("mass", p.mass);
      f("sxx", p.sxx), f("syy", p.syy), f("szz", p.szz), f("sxy", p.sxy), f("sxz", p.sxz), f("syz", p.syz);
      f("rxx", p.rxx), f("ryy", p.ryy), f("rzz", p.rzz), f("rxy", p.rxy), f("rxz", p.rxz), f("ryz", p.ryz);
      f("ax", p.ax), f("ay", p.ay), f("az", p.az), f("density_rate", p.density_rate);
      f("lxx", p.lxx), f("lxy", p.lxy), f("lxz", p.lxz), f("lyx", p.lyx), f("lyy", p.lyy), f("lyz", p.lyz);
      f("lzx", p.lzx), f("lzy", p.lzy), f("lzz", p.lzz);
      f("x0", p.x0), f("y0", p.y0), f("z0", p.z0);
    }
  }
  template <class Self, class F>
  static void for_each_wall_array_of(Self& p, F& f) {
    f(p.wall_nx), f(p.wall_ny), f(p.wall_vx), f(p.wall_vy), f(p.wall_friction), f(p.wall_stick);
    if constexpr (dim == 3) f(p.wall_nz), f(p.wall_vz), f(p.image_sign_x), f(p.image_sign_y), f(p.image_sign_z);
  }
};

/// The plane-strain solver's particles.
using Particles = ParticlesOf<2>;

}  // namespace soilsph::sph
