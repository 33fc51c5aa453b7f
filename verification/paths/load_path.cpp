#include "verification/paths/load_path.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "constitutive/parameters.h"

namespace soilsph::verification {

namespace {

/// "NAME = VALUE is out of range (allowed: ...)" unless `range` holds `value`.
void require(std::string_view name, double value, const Range& range, std::string_view unit = "") {
  if (range.contains(value)) return;
  throw std::invalid_argument(std::string(name) + " = " + format_number(value) +
                              " is out of range (allowed: " + range.describe() + (unit.empty() ? "" : " ") +
                              std::string(unit) + ")");
}

constexpr std::string_view kComponents[3][3] = {
    {"d_xx", "d_xy", "d_xz"}, {"d_xy", "d_yy", "d_yz"}, {"d_xz", "d_yz", "d_zz"}};

/// Each increment of a strain path, and the strain accumulated up to it, within the small-strain range.
void validate_strain_path(const PointTest& test) {
  if (test.strain_increments.empty()) throw std::invalid_argument("the strain path has no increments");
  Mat3 total = Mat3::Zero();
  for (std::size_t n = 0; n < test.strain_increments.size(); ++n) {
    const Mat3& d = test.strain_increments[n];
    total += d;
    const std::string where = describe_increment(test, n, 0) + ": ";
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        const std::string name(kComponents[i][j]);
        require(where + name, d(i, j), point_limits::strain());
        require(where + "eps_" + name.substr(2) + " accumulated up to this row", total(i, j),
                point_limits::strain());
      }
    }
  }
}

void validate(const PointTest& test) {
  require("p_initial", test.p_initial, point_limits::p_initial(), "Pa");
  require("ocr", test.ocr, point_limits::ocr());
  if (test.path == LoadPath::StrainPath) return validate_strain_path(test);
  require("increments", test.increments, Range::closed(1, point_limits::kMaxIncrements));
  if (test.strain_targets.empty()) throw std::invalid_argument("strain_targets is empty");
  double previous = 0.0;
  for (double target : test.strain_targets) {
    require("strain target", target, point_limits::strain());
    if (target == previous)
      throw std::invalid_argument("strain target " + format_number(target) + " gives a leg of zero length");
    previous = target;
  }
}

/// Voigt strain increment (tension-positive) for a driven-strain step `d` (compression-positive).
Vec6 driven_strain(LoadPath path, double d) {
  Vec6 e = Vec6::Zero();
  switch (path) {
    case LoadPath::TriaxialDrained:
    case LoadPath::TriaxialUndrained:
    case LoadPath::Oedometer:
      e(0) = -d;
      break;
    case LoadPath::Isotropic:  // d is ε_v
      e.head<3>().setConstant(-d / 3.0);
      break;
    case LoadPath::StrainPath:
      break;
  }
  return e;
}

}  // namespace

std::string describe_leg(const PointTest& test, std::size_t leg) {
  if (test.path == LoadPath::StrainPath) {
    if (leg < test.strain_increment_sources.size()) return test.strain_increment_sources[leg];
    return "row " + std::to_string(leg + 1) + " of the strain path";
  }
  const std::string driven = test.path == LoadPath::Isotropic ? "eps_v" : "eps_a";
  const double from = leg == 0 ? 0.0 : test.strain_targets[leg - 1];
  return "leg " + std::to_string(leg + 1) + " (" + driven + " from " + format_number(from) + " to " +
         format_number(test.strain_targets[leg]) + ")";
}

std::string describe_increment(const PointTest& test, std::size_t leg, int increment) {
  if (test.path == LoadPath::StrainPath) return describe_leg(test, leg);
  return "increment " + std::to_string(increment + 1) + " of " + std::to_string(test.increments) + " of " +
         describe_leg(test, leg);
}

Leg resolve_leg(const Leg& leg, const PointSample& start) {
  Leg resolved = leg;
  const Vec6 strain = strain_to_voigt(start.strain);
  Vec6 total = stress_to_voigt(start.state.stress);
  if (leg.undrained) total.head<3>().array() -= start.pore_pressure;
  for (int k = 0; k < 6; ++k) {
    if (std::isnan(leg.target[k])) continue;
    const double reached = leg.stress_imposed[k] ? total(k) : strain(k);
    resolved.increment(k) = (leg.target[k] - reached) / leg.increments;
  }
  return resolved;
}

std::vector<Leg> build_legs(const PointTest& test) {
  validate(test);
  std::vector<Leg> legs;
  if (test.path == LoadPath::StrainPath) {
    for (const Mat3& d : test.strain_increments) legs.push_back({{}, strain_to_voigt(d), 1});
    return legs;
  }
  // Triaxial: the radial stresses are imposed with zero increment, held at −p_initial (total
  // stresses when undrained, with the volume held and the pore pressure solved for).
  std::array<bool, 6> stress_imposed{};
  const bool triaxial = test.path == LoadPath::TriaxialDrained || test.path == LoadPath::TriaxialUndrained;
  if (triaxial) stress_imposed[1] = stress_imposed[2] = true;
  double previous = 0.0;
  for (double target : test.strain_targets) {
    const double step = (target - previous) / test.increments;
    legs.push_back({stress_imposed, driven_strain(test.path, step), test.increments,
                    test.path == LoadPath::TriaxialUndrained});
    previous = target;
  }
  return legs;
}

}  // namespace soilsph::verification
