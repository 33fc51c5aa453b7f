#pragma once
/// @file
/// One point of a closed-form reference curve, in the soil-mechanics convention of the driver's
/// output: compression-positive, SI units (Pa, strain as a fraction).
namespace soilsph::verification {

struct ReferencePoint {
  double eps_a;  ///< axial strain (the driven strain of triaxial and oedometer paths)
  double eps_v;  ///< volumetric strain
  double p;      ///< mean effective stress p'
  double q;      ///< deviatoric stress
  double p_c;    ///< MCC preconsolidation pressure (0 for Drucker–Prager)
};

}  // namespace soilsph::verification
