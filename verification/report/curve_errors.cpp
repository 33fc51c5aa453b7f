#include "verification/report/curve_errors.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "verification/closed_form/closed_form.h"

namespace soilsph::verification {

namespace {
/// Driven strains of two rows that compare as the same sample (increments are equal by construction).
constexpr double kSameStrain = 1e-9;
}  // namespace

CurveErrors curve_errors(const PointCurve& curve, std::span<const ReferencePoint> reference, LoadPath path) {
  if (curve.size() != reference.size())
    throw std::invalid_argument("curve and reference differ in length (" + std::to_string(curve.size()) +
                                " vs " + std::to_string(reference.size()) + " rows)");
  double stress_scale = 0.0, strain_scale = 0.0;
  for (const ReferencePoint& r : reference) {
    stress_scale = std::max({stress_scale, std::abs(r.p), std::abs(r.q)});
    strain_scale = std::max({strain_scale, std::abs(r.eps_a), std::abs(r.eps_v)});
  }
  CurveErrors e;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const PointRecord& c = curve[i];
    const ReferencePoint& r = reference[i];
    const double reference_driven = path == LoadPath::Isotropic ? r.eps_v : r.eps_a;
    if (std::abs(driven_strain(c, path) - reference_driven) > kSameStrain)
      throw std::invalid_argument("curve and reference sampled at different strains (row " +
                                  std::to_string(i) + ")");
    e.q = std::max(e.q, std::abs(c.q - r.q));
    e.p = std::max(e.p, std::abs(c.p - r.p));
    e.eps_v = std::max(e.eps_v, std::abs(c.eps_v - r.eps_v));
  }
  if (stress_scale > 0.0) e.q /= stress_scale, e.p /= stress_scale;
  if (strain_scale > 0.0) e.eps_v /= strain_scale;
  return e;
}

std::vector<ReferencePoint> as_reference(const PointCurve& curve) {
  std::vector<ReferencePoint> out;
  out.reserve(curve.size());
  for (const PointRecord& r : curve) out.push_back({r.eps_a, r.eps_v, r.p, r.q, r.p_c});
  return out;
}

}  // namespace soilsph::verification
