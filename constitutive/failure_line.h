#pragma once
/// @file
/// Where a model fails on the triaxial-compression meridian, as a straight line in the p′–q plane
/// (compression-positive): q = slope · p′ + intercept. For D-P and Mohr–Coulomb it is the yield
/// surface itself; for Modified Cam-Clay the critical-state line q = M p′ that every drained or
/// undrained path ends on. Reports and plots draw it without asking which model they have.

namespace soilsph {

struct FailureLine {
  double slope;      ///< dq/dp′ on triaxial compression
  double intercept;  ///< q at p′ = 0 (Pa)
};

}  // namespace soilsph
