#include "verification/point_test.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <stdexcept>
#include <string>

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

}  // namespace

PointCurve run_point_test(const Material& material, const PointTest& test, std::string_view integrator) {
  const std::vector<Leg> legs = build_legs(test);
  const State initial = initial_state(material, test);
  PointHistory history;
  if (integrator == kReferenceIntegrator) {
    history = cvode_reference(material, initial, legs);
  } else {
    const Material chosen = with_integrator(material, parse_integrator(integrator));
    history =
        std::visit([&](const auto& model) { return drive_mixed_control(model, initial, legs); }, chosen);
  }
  PointCurve curve;
  curve.reserve(history.size());
  for (const PointSample& sample : history) curve.push_back(to_record(sample, initial, test.path));
  return curve;
}

void write_point_csv(std::ostream& out, const PointCurve& curve) {
  // The comment line holds no commas, so CSV readers that take it for a row still see one field.
  out << "# soilsph point: compression-positive; SI (strains 1; stresses Pa); axial = x; radial = mean of y "
         "and z; "
         "eps_q = 2/3 (eps_a - eps_r); q = sqrt(3 J2) signed as sig_a - sig_r; p_c = MCC preconsolidation "
         "pressure (0 otherwise); u = undrained excess pore pressure (0 otherwise)\n"
      << "eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u\n";
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

}  // namespace soilsph::verification
