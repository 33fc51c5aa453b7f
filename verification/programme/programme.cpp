#include "verification/programme/programme.h"

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "constitutive/material_description.h"
#include "verification/driver/mixed_control.h"
#include "verification/reference/cvode_reference.h"

namespace soilsph::verification {

namespace {

/// The soil-mechanics measures of one sample, compression-positive.
PointRecord to_record(const PointSample& sample) {
  const Mat3& e = sample.strain;
  const Mat3& s = sample.state.stress;
  // "+ 0.0" below turns the −0 of negated zero components into 0 in the output.
  PointRecord r{};
  r.eps_a = -e(0, 0) + 0.0;
  r.eps_r = -0.5 * (e(1, 1) + e(2, 2)) + 0.0;
  r.eps_v = volumetric_strain(e) + 0.0;
  r.eps_q = 2.0 / 3.0 * (r.eps_a - r.eps_r);
  r.sig_a = -s(0, 0);
  r.sig_r = -0.5 * (s(1, 1) + s(2, 2));
  r.p = mean_pressure(s);
  r.q = std::copysign(deviatoric_stress(s), r.sig_a - r.sig_r);
  r.p_c = sample.state.pc;
  r.u = sample.pore_pressure + 0.0;
  r.tau_xy = -s(0, 1) + 0.0;
  r.gamma_xy = -2.0 * e(0, 1) + 0.0;
  return r;
}

/// Why `sample` has lost meaning (the bounds of run_point_test), or "" if it has not.
std::string lost_meaning(const PointSample& sample) {
  const State& s = sample.state;
  if (!sample.strain.allFinite() || !s.stress.allFinite() || !std::isfinite(s.pc) ||
      !std::isfinite(sample.pore_pressure))
    return "a value is not finite";
  const auto beyond = [](std::string_view what, double value, double bound, std::string_view unit) {
    return std::string(what) + " = " + format_number(value) + std::string(unit) + " is beyond " +
           format_number(bound) + std::string(unit);
  };
  const double stress = s.stress.cwiseAbs().maxCoeff();
  if (stress > limits::kMaxStress)
    return beyond("the largest |stress component|", stress, limits::kMaxStress, " Pa");
  if (s.pc > limits::kMaxStress) return beyond("p_c", s.pc, limits::kMaxStress, " Pa");
  if (std::abs(sample.pore_pressure) > limits::kMaxStress)
    return beyond("|u|", std::abs(sample.pore_pressure), limits::kMaxStress, " Pa");
  const double strain = sample.strain.cwiseAbs().maxCoeff();
  if (strain > point_limits::kMaxResultStrain)
    return beyond("the largest |strain component|", strain, point_limits::kMaxResultStrain, "");
  return "";
}

std::string describe(const Programme& programme, std::size_t leg, int increment) {
  if (programme.legs_are_rows) return programme.leg_names[leg];
  return "increment " + std::to_string(increment + 1) + " of " +
         std::to_string(programme.legs[leg].increments) + " of " + programme.leg_names[leg];
}

PointCurve curve_of(const PointHistory& history) {
  PointCurve curve;
  curve.reserve(history.size());
  for (const PointSample& sample : history) curve.push_back(to_record(sample));
  return curve;
}

/// Throws, naming the increment, at the first sample of `history` that has lost meaning.
void check_meaning(const PointHistory& history, const Programme& programme) {
  std::size_t leg = 0;
  int increment = -1;  // sample 0 is the initial state
  for (const PointSample& sample : history) {
    if (const std::string why = lost_meaning(sample); !why.empty()) {
      const std::string where = increment < 0 ? "the initial state" : describe(programme, leg, increment);
      throw std::runtime_error(where + ": the result has lost meaning: " + why +
                               " (smaller strains, more increments or another integrator may help)");
    }
    if (++increment == programme.legs[leg].increments && leg + 1 < programme.legs.size()) {
      ++leg;
      increment = 0;
    }
  }
}

}  // namespace

Programme programme_of(const Material& material, const PointTest& test) {
  Programme programme;
  programme.legs = build_legs(test);
  programme.initial.stress = isotropic_stress(test.p_initial);
  programme.initial.pc = initial_preconsolidation(material, programme.initial.stress, test.ocr);
  programme.legs_are_rows = test.path == LoadPath::StrainPath;
  if (!(test.path_tolerance == 0.0 || point_limits::path_tolerance().contains(test.path_tolerance)))
    throw std::invalid_argument("path_tolerance = " + format_number(test.path_tolerance) +
                                " is out of range (allowed: 0 (off) or " +
                                point_limits::path_tolerance().describe() + ")");
  programme.path_tolerance = test.path_tolerance;
  for (std::size_t l = 0; l < programme.legs.size(); ++l)
    programme.leg_names.push_back(describe_leg(test, l));
  return programme;
}

PointCurve run_programme(const Material& material, const Programme& programme, std::string_view integrator) {
  PointHistory history;
  try {
    if (integrator == kReferenceIntegrator) {
      history = cvode_reference(material, programme.initial, programme.legs);
    } else {
      const Material chosen = with_integrator(material, parse_integrator(integrator));
      MixedControlOptions options;
      options.path_tolerance = programme.path_tolerance;
      history = std::visit(
          [&](const auto& model) {
            return drive_mixed_control(model, programme.initial, programme.legs, options);
          },
          chosen);
    }
  } catch (const IncrementError& e) {
    const std::string message = describe(programme, e.leg, e.increment) + ": " + e.reason;
    if (e.completed.empty()) throw std::runtime_error(message);
    check_meaning(e.completed, programme);
    throw StrengthReachedError(message, curve_of(e.completed));
  }
  check_meaning(history, programme);
  return curve_of(history);
}

}  // namespace soilsph::verification
