#pragma once
/// @file
/// A read-only view of the soil particles at one instant: what the solver hands to the writers.
///
/// Conventions (see docs/sph-output.md): SI units; 2D plane strain in x (horizontal) and y (vertical,
/// up); stress components tension-positive as inside the solver (paper eq 9–10); p and q
/// compression-positive soil-mechanics invariants (constitutive/tensor.h).
#include <span>

namespace soilsph::sph {

/// A read-only view of the soil particles at one instant (boundary particles excluded unless noted).
/// Every span has one entry per particle and they all have the same length.
struct Frame {
  double time = 0.0;                           ///< s
  std::span<const double> x, y, vx, vy;        ///< m, m/s
  std::span<const double> sxx, syy, szz, sxy;  ///< Pa, tension-positive stress components
  std::span<const double> p, q;                ///< Pa, compression-positive p, von Mises q
  std::span<const double> plastic_strain;      ///< accumulated equivalent plastic strain
  std::span<const double> density;             ///< kg/m^3
  std::span<const int> layer;                  ///< horizontal layer id (0,1,2,... from the bottom)
};

}  // namespace soilsph::sph
