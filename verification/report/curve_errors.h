#pragma once
/// @file
/// Maximum relative errors of a material-point curve against a reference curve sampled at the same
/// driven strains. An error is max over rows of |x − x_ref|, divided by a scale of the whole reference
/// curve: stresses (q, p') by its largest |p'| or |q|, strains (ε_v) by its largest |ε_a| or |ε_v|.
/// Curve-wide scales keep the measure finite where a quantity crosses or stays at zero (q on the
/// isotropic path, ε_v undrained) and weight every row alike.
#include <algorithm>
#include <span>

#include "verification/closed_form/reference_point.h"
#include "verification/point_test.h"

namespace soilsph::verification {

struct CurveErrors {
  double q = 0.0;
  double p = 0.0;
  double eps_v = 0.0;
  double max() const { return std::max({q, p, eps_v}); }
};

/// Errors of `curve` against `reference` (same rows); throws std::invalid_argument if the row
/// counts differ or the driven strains of a row differ by more than 1e-9.
CurveErrors curve_errors(const PointCurve& curve, std::span<const ReferencePoint> reference, LoadPath path);
/// The reference points of a driver curve (e.g. the CVODE one), to compare curves with each other.
std::vector<ReferencePoint> as_reference(const PointCurve& curve);

}  // namespace soilsph::verification
