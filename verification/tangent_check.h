#pragma once
/// @file
/// The tangent check (`soilsph material FILE --check-tangent`): along a material-point path, the
/// tangent a model returns for each increment (a UMAT's DDSDDE, a built-in model's consistent
/// tangent) against a central finite difference of its stress update over the same increment
/// (constitutive/tangent.h). A wrong DDSDDE is the most common UMAT bug: it slows or breaks Newton
/// at a point and in a finite-element code, while the stresses stay right.
#include <vector>

#include "constitutive/material.h"
#include "verification/programme/programme.h"

namespace soilsph::verification {

/// One increment's comparison. Each component's error is relative to the largest entry of the
/// finite-difference tangent, |T_ij − F_ij| / max_kl |F_kl|, so that entries that vanish are judged
/// on the tangent's scale.
struct TangentCheckRow {
  int increment = 0;            ///< from 1, along the whole path
  Mat6 relative_error;          ///< per component (Voigt 11, 22, 33, 12, 13, 23)
  double max_error() const { return relative_error.maxCoeff(); }
};

/// Runs `programme` with the model's own update, then compares the tangents at every increment.
std::vector<TangentCheckRow> check_tangent(const Material& material, const Programme& programme);

}  // namespace soilsph::verification
