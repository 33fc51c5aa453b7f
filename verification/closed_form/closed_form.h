#pragma once
/// @file
/// The closed-form references by name, so that verification cases (verification/cases/*.toml) choose
/// them as data. Each applies to one model and one load path; see the class headers for the formulas.
#include <span>
#include <string_view>
#include <vector>

#include "verification/closed_form/reference_point.h"
#include "verification/point_test.h"

namespace soilsph::verification {

/// Names accepted by closed_form_curve(); "none" means the case has no closed form.
inline constexpr std::string_view kClosedFormNames[] = {
    "none",         "dp-triaxial-drained",    "dp-triaxial-undrained", "dp-oedometer",
    "dp-isotropic", "mcc-triaxial-undrained", "mcc-triaxial-drained",  "mcc-isotropic",
    "mcc-oedometer", "mc-triaxial-drained", "mc-triaxial-undrained"};

/// The driven strain of a row: volumetric on the isotropic path, axial otherwise (compression-positive).
double driven_strain(const PointRecord& row, LoadPath path);

/// The named closed form at the driven strains `driven` (visited in order) of `test` on `material`.
/// Throws std::invalid_argument when the name is unknown or the closed form does not apply to the
/// material, its elasticity, the path or the loading programme (e.g. unloading on a triaxial path).
std::vector<ReferencePoint> closed_form_curve(std::string_view name, const Material& material,
                                              const PointTest& test, std::span<const double> driven);

}  // namespace soilsph::verification
