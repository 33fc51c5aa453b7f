#pragma once
/// @file
/// The particles as a structure of arrays. Soil particles come first, [0, soil_count); the fixed
/// boundary (ghost) particles follow, [soil_count, size()). Every array has size() entries except
/// `state` and `layer`, which belong to the soil only.
#include <cstdint>
#include <vector>

#include "constitutive/state.h"

namespace soilsph::sph {

/// What a boundary particle represents; it decides how it mirrors the soil (see stages/boundaries.h).
enum class BoundaryKind : std::uint8_t {
  FreeSlipWall,  ///< a vertical wall: normal velocity and shear stress mirrored, tangential copied
  NoSlipFloor,   ///< the floor: velocity mirrored (zero at the wall), stress copied
};

struct Particles {
  std::size_t soil_count = 0;  ///< soil particles are the first soil_count entries

  // Every particle (soil then boundary).
  std::vector<double> x, y;           ///< position (m)
  std::vector<double> vx, vy;         ///< velocity (m/s); at half steps for the soil (leapfrog)
  std::vector<double> density;        ///< kg/m³
  std::vector<double> mass;           ///< kg per metre of thickness (plane strain)
  std::vector<double> sxx, syy, sxy;  ///< in-plane stress used by the momentum equation (Pa)
  std::vector<double> rxx, ryy, rxy;  ///< artificial stress (Gray et al. 2001), divided by ρ² (m²/s²)
  std::vector<double> sxx_rho2, syy_rho2, sxy_rho2;  ///< σ/ρ² (m²/s²), once per particle for every pair

  // Soil only.
  std::vector<double> ax, ay;              ///< acceleration (m/s²)
  std::vector<double> density_rate;        ///< Dρ/Dt, eq 11 (kg/m³/s)
  std::vector<double> lxx, lxy, lyx, lyy;  ///< velocity gradient ∂v^α/∂x^β, eq 23 (1/s)
  std::vector<State> state;                ///< full 3×3 stress and hardening state
  std::vector<int> layer;                  ///< horizontal layer id from the bottom (for pictures)

  // Boundary only, indexed by (i − soil_count).
  std::vector<BoundaryKind> boundary_kind;

  std::size_t size() const { return x.size(); }
  std::size_t boundary_count() const { return size() - soil_count; }
  bool is_soil(std::size_t i) const { return i < soil_count; }

  /// Bytes held by the arrays.
  std::size_t bytes() const {
    std::size_t b =
        state.capacity() * sizeof(State) + layer.capacity() * sizeof(int) + boundary_kind.capacity();
    for (const auto* a :
         {&x,   &y,        &vx,       &vy,       &density, &mass, &sxx,          &syy, &sxy, &rxx, &ryy,
          &rxy, &sxx_rho2, &syy_rho2, &sxy_rho2, &ax,      &ay,   &density_rate, &lxx, &lxy, &lyx, &lyy})
      b += a->capacity() * sizeof(double);
    return b;
  }

  /// Sizes every array for `soil` soil and `boundary` boundary particles (zero-filled).
  void resize(std::size_t soil, std::size_t boundary) {
    soil_count = soil;
    const std::size_t n = soil + boundary;
    for (auto* a : {&x, &y, &vx, &vy, &density, &mass, &sxx, &syy, &sxy, &rxx, &ryy, &rxy, &sxx_rho2,
                    &syy_rho2, &sxy_rho2})
      a->assign(n, 0.0);
    for (auto* a : {&ax, &ay, &density_rate, &lxx, &lxy, &lyx, &lyy}) a->assign(soil, 0.0);
    state.assign(soil, State{});
    layer.assign(soil, 0);
    boundary_kind.assign(boundary, BoundaryKind::NoSlipFloor);
  }
};

}  // namespace soilsph::sph
