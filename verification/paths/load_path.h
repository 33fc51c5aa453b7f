#pragma once
/// @file
/// Load paths as data: each path is a list of legs, and each leg says, for every Voigt component
/// (xx, yy, zz, xy, yz, xz; voigt.h), whether the stress or the strain is imposed and by how much per
/// increment. The mixed-control driver and the CVODE reference both consume legs, so they solve
/// exactly the same problem.
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "constitutive/voigt.h"
#include "verification/driver/point_history.h"
#include "verification/point_test.h"

namespace soilsph::verification {

/// One leg: `increments` equal increments of a constant control.
struct Leg {
  /// true: the stress component is imposed (its strain is free); false: the strain is imposed.
  std::array<bool, 6> stress_imposed{};
  /// Per increment, tension-positive: the strain increment (Voigt, engineering shears) of
  /// strain-imposed components, the stress increment (Pa) of stress-imposed components.
  Vec6 increment = Vec6::Zero();
  int increments = 1;
  /// Undrained: the imposed stresses are total stresses σ' − u δ, and the volume is held (ε_v
  /// constant), with the pore pressure u solved for. Drained legs have u = 0 (any excess from an
  /// earlier undrained leg has dissipated at their start).
  bool undrained = false;
  /// Per component, optional (NaN: none): the value to reach at the leg's end, strain (Voigt) or
  /// total stress (Pa) as the component is imposed, tension-positive. resolve_leg() turns it into
  /// `increment` from the state the leg starts from, which a programme cannot know in advance.
  std::array<double, 6> target = kNoTargets;
  static constexpr std::array<double, 6> kNoTargets = {NAN, NAN, NAN, NAN, NAN, NAN};
};

/// `leg` with the increments of its targets from `start`: (target − value at start) / increments.
Leg resolve_leg(const Leg& leg, const PointSample& start);

/// The legs of `test`, validated: p_initial, ocr, increments, each strain target and each
/// strain-path increment and its running sum within point_limits, legs of non-zero length, a
/// non-empty strain path; throws std::invalid_argument naming the offending field or row.
///  - triaxial-drained:   ε_xx driven, σ_yy, σ_zz held (stress imposed, zero increment), shear strains 0;
///  - triaxial-undrained: ε_xx driven, total σ_yy, σ_zz held, undrained (ε_v = 0, u solved), shear strains 0;
///  - oedometer:          ε_xx driven, all other strains 0;
///  - isotropic:          ε_xx = ε_yy = ε_zz = −ε_v/3 driven, shear strains 0;
///  - strain-path:        every strain component imposed, one increment per given tensor.
std::vector<Leg> build_legs(const PointTest& test);

/// Names leg `leg` (from 0) of `test`: "leg 2 (eps_a from 0.1 to 0.05)", or a strain-path row's
/// "FILE:LINE" (test.strain_increment_sources) or "row N of the strain path".
std::string describe_leg(const PointTest& test, std::size_t leg);
/// Names increment `increment` of leg `leg` (both from 0) of `test` for messages: the strain-path
/// row's "FILE:LINE" (test.strain_increment_sources) or "row N of the strain path", else e.g.
/// "increment 3 of 100 of leg 2 (eps_a from 0.1 to 0.05)".
std::string describe_increment(const PointTest& test, std::size_t leg, int increment);

}  // namespace soilsph::verification
