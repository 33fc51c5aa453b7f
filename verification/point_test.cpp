#include "verification/point_test.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "constitutive/material_description.h"
#include "verification/programme/programme.h"

namespace soilsph::verification {

namespace {

constexpr std::string_view kPathNames[] = {"triaxial-drained", "triaxial-undrained", "oedometer", "isotropic",
                                           "strain-path"};

}  // namespace

PointCurve run_point_test(const Material& material, const PointTest& test, std::string_view integrator) {
  return run_programme(material, programme_of(material, test), integrator);
}

void write_point_csv(std::ostream& out, const PointCurve& curve, std::span<const std::string> comments) {
  // The comment line holds no commas, so CSV readers that take it for a row still see one field.
  out << "# soilsph point: compression-positive; SI (strains 1; stresses Pa); axial = x; radial = mean of y "
         "and z; "
         "eps_q = 2/3 (eps_a - eps_r); q = sqrt(3 J2) signed as sig_a - sig_r; p_c = MCC preconsolidation "
         "pressure (0 otherwise); u = undrained excess pore pressure (0 otherwise); tau_xy = -sig_xy and "
         "gamma_xy = -2 eps_xy (shear of the compression-positive tensors)\n";
  for (const std::string& line : comments) {
    // A line break inside (a quoted argument of the command line) would end the comment early.
    out << "# ";
    for (const char c : line) out << (c == '\n' ? "\\n" : c == '\r' ? "\\r" : std::string(1, c));
    out << '\n';
  }
  out << "eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u,tau_xy,gamma_xy\n";
  const auto flags = out.flags();
  const auto precision = out.precision();
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for (const PointRecord& r : curve) {
    out << r.eps_a << ',' << r.eps_r << ',' << r.eps_v << ',' << r.eps_q << ',' << r.sig_a << ',' << r.sig_r
        << ',' << r.p << ',' << r.q << ',' << r.p_c << ',' << r.u << ',' << r.tau_xy << ',' << r.gamma_xy << '\n';
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
