#include "verification/paths/load_path.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace soilsph::verification {

namespace {

void validate(const PointTest& test) {
  if (!(test.p_initial > 0.0) || !std::isfinite(test.p_initial))
    throw std::invalid_argument("p_initial must be > 0 Pa, got " + std::to_string(test.p_initial));
  if (!(test.ocr >= 1.0) || !std::isfinite(test.ocr))
    throw std::invalid_argument("ocr must be >= 1, got " + std::to_string(test.ocr));
  if (test.path == LoadPath::StrainPath) {
    if (test.strain_increments.empty()) throw std::invalid_argument("the strain path has no increments");
    return;
  }
  if (test.increments < 1)
    throw std::invalid_argument("increments must be >= 1, got " + std::to_string(test.increments));
  if (test.strain_targets.empty()) throw std::invalid_argument("strain_targets is empty");
  double previous = 0.0;
  for (double target : test.strain_targets) {
    if (!std::isfinite(target)) throw std::invalid_argument("strain target is not finite");
    if (target == previous)
      throw std::invalid_argument("strain target " + std::to_string(target) + " gives a leg of zero length");
    previous = target;
  }
}

/// Voigt strain increment (tension-positive) for a driven-strain step `d` (compression-positive).
Vec6 driven_strain(LoadPath path, double d) {
  Vec6 e = Vec6::Zero();
  switch (path) {
    case LoadPath::TriaxialDrained:
    case LoadPath::Oedometer:
      e(0) = -d;
      break;
    case LoadPath::TriaxialUndrained:  // tr = 0
      e.head<3>() << -d, 0.5 * d, 0.5 * d;
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

std::vector<Leg> build_legs(const PointTest& test) {
  validate(test);
  std::vector<Leg> legs;
  if (test.path == LoadPath::StrainPath) {
    for (const Mat3& d : test.strain_increments) legs.push_back({{}, strain_to_voigt(d), 1});
    return legs;
  }
  // Drained triaxial: the radial stresses are imposed with zero increment (held at −p_initial).
  std::array<bool, 6> stress_imposed{};
  if (test.path == LoadPath::TriaxialDrained) stress_imposed[1] = stress_imposed[2] = true;
  double previous = 0.0;
  for (double target : test.strain_targets) {
    const double step = (target - previous) / test.increments;
    legs.push_back({stress_imposed, driven_strain(test.path, step), test.increments});
    previous = target;
  }
  return legs;
}

}  // namespace soilsph::verification
