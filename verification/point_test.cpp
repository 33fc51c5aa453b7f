#include "verification/point_test.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "constitutive/material_description.h"
#include "verification/driver/mixed_control.h"
#include "verification/paths/load_path.h"
#include "verification/reference/cvode_reference.h"

namespace soilsph::verification {

namespace {

constexpr std::string_view kPathNames[] = {"triaxial-drained", "triaxial-undrained", "oedometer", "isotropic",
                                           "strain-path"};

/// Isotropic effective stress p_initial; MCC gets p_c0 = OCR · p_initial.
State initial_state(const Material& material, const PointTest& test) {
  State state;
  state.stress = isotropic_stress(test.p_initial);
  if (std::holds_alternative<ModifiedCamClay>(material)) state.pc = test.ocr * test.p_initial;
  return state;
}

/// The soil-mechanics measures of one sample, compression-positive.
PointRecord to_record(const PointSample& sample, const State& initial, LoadPath path) {
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
  if (path == LoadPath::TriaxialUndrained) {
    // Radial total stress constant: Δσ_r' + u = 0, so u = σ_r'(0) − σ_r' (= Δq/3 − Δp').
    r.u = -0.5 * (initial.stress(1, 1) + initial.stress(2, 2)) - r.sig_r;
  }
  return r;
}

/// Why `sample` has lost meaning (the bounds of run_point_test), or "" if it has not.
std::string lost_meaning(const PointSample& sample) {
  const State& s = sample.state;
  if (!sample.strain.allFinite() || !s.stress.allFinite() || !std::isfinite(s.pc))
    return "a value is not finite";
  const auto beyond = [](std::string_view what, double value, double bound, std::string_view unit) {
    return std::string(what) + " = " + format_number(value) + std::string(unit) + " is beyond " +
           format_number(bound) + std::string(unit);
  };
  const double stress = s.stress.cwiseAbs().maxCoeff();
  if (stress > limits::kMaxStress)
    return beyond("the largest |stress component|", stress, limits::kMaxStress, " Pa");
  if (s.pc > limits::kMaxStress) return beyond("p_c", s.pc, limits::kMaxStress, " Pa");
  const double strain = sample.strain.cwiseAbs().maxCoeff();
  if (strain > point_limits::kMaxResultStrain)
    return beyond("the largest |strain component|", strain, point_limits::kMaxResultStrain, "");
  return "";
}

/// Throws, naming the increment, at the first sample of `history` that has lost meaning.
void check_meaning(const PointHistory& history, const PointTest& test, std::span<const Leg> legs) {
  std::size_t leg = 0;
  int increment = -1;  // sample 0 is the initial state
  for (const PointSample& sample : history) {
    if (const std::string why = lost_meaning(sample); !why.empty()) {
      const std::string where =
          increment < 0 ? "the initial state" : describe_increment(test, leg, increment);
      throw std::runtime_error(where + ": the result has lost meaning: " + why +
                               " (smaller strains, more increments or another integrator may help)");
    }
    if (++increment == legs[leg].increments && leg + 1 < legs.size()) {
      ++leg;
      increment = 0;
    }
  }
}

}  // namespace

PointCurve run_point_test(const Material& material, const PointTest& test, std::string_view integrator) {
  const std::vector<Leg> legs = build_legs(test);
  const State initial = initial_state(material, test);
  PointHistory history;
  try {
    if (integrator == kReferenceIntegrator) {
      history = cvode_reference(material, initial, legs);
    } else {
      const Material chosen = with_integrator(material, parse_integrator(integrator));
      history =
          std::visit([&](const auto& model) { return drive_mixed_control(model, initial, legs); }, chosen);
    }
  } catch (const IncrementError& e) {
    throw std::runtime_error(describe_increment(test, e.leg, e.increment) + ": " + e.reason);
  }
  check_meaning(history, test, legs);
  PointCurve curve;
  curve.reserve(history.size());
  for (const PointSample& sample : history) curve.push_back(to_record(sample, initial, test.path));
  return curve;
}

void write_point_csv(std::ostream& out, const PointCurve& curve, std::span<const std::string> comments) {
  // The comment line holds no commas, so CSV readers that take it for a row still see one field.
  out << "# soilsph point: compression-positive; SI (strains 1; stresses Pa); axial = x; radial = mean of y "
         "and z; "
         "eps_q = 2/3 (eps_a - eps_r); q = sqrt(3 J2) signed as sig_a - sig_r; p_c = MCC preconsolidation "
         "pressure (0 otherwise); u = undrained excess pore pressure (0 otherwise)\n";
  for (const std::string& line : comments) {
    // A line break inside (a quoted argument of the command line) would end the comment early.
    out << "# ";
    for (const char c : line) out << (c == '\n' ? "\\n" : c == '\r' ? "\\r" : std::string(1, c));
    out << '\n';
  }
  out << "eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u\n";
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const PointRecord& r : curve) {
    out << r.eps_a << ',' << r.eps_r << ',' << r.eps_v << ',' << r.eps_q << ',' << r.sig_a << ',' << r.sig_r
        << ',' << r.p << ',' << r.q << ',' << r.p_c << ',' << r.u << '\n';
  }
  out.flags(flags);
  out.precision(precision);
}

LoadPath parse_load_path(std::string_view name) {
  for (std::size_t k = 0; k < std::size(kPathNames); ++k)
    if (name == kPathNames[k]) return static_cast<LoadPath>(k);
  std::string allowed;
  for (std::string_view n : kPathNames) {
    if (!allowed.empty()) allowed += ", ";
    allowed += n;
  }
  throw std::invalid_argument("unknown test \"" + std::string(name) + "\" (allowed: " + allowed + ")");
}

std::string_view load_path_name(LoadPath path) {
  return kPathNames[static_cast<int>(path)];
}

std::string describe_test(const PointTest& test, std::string_view strain_path_file) {
  std::string loading;
  if (test.path == LoadPath::StrainPath) {
    loading = "strain path " + std::string(strain_path_file) + " (" + std::to_string(test.strain_increments.size()) +
              " rows; one increment each)";
  } else {
    loading = std::string(test.path == LoadPath::Isotropic ? "eps_v" : "eps_a") + " targets";
    for (double target : test.strain_targets) loading += " " + exact_number(target);
    loading += " (" + std::to_string(test.increments) + " increments each)";
  }
  return std::string(load_path_name(test.path)) + "; p_initial = " + exact_number(test.p_initial) +
         " Pa; ocr = " + exact_number(test.ocr) + "; " + loading;
}

}  // namespace soilsph::verification
