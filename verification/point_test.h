#pragma once
/// @file
/// The material-point test: one load path (triaxial, oedometer, isotropic or a strain-path file)
/// applied to one material with a chosen integrator, or with the CVODE reference. Inputs and outputs
/// are compression-positive and SI; internally the driver works tension-positive (tensor.h).
/// Axes: axial = x (index 0), radial = y and z (indices 1, 2).
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "constitutive/material.h"
#include "constitutive/material_limits.h"

namespace soilsph::verification {

/// Where a test's inputs keep their meaning (docs/guide/material-point-tests.md); run_point_test rejects
/// anything outside with std::invalid_argument.
namespace point_limits {
/// |strain| of a target, a strain-path increment and the strain accumulated along a path, below 1:
/// the models are small-strain, and a volumetric strain of 1 would leave no volume.
inline constexpr double kMaxStrain = 1.0;
/// A result whose |strain| exceeds this (ten times any imposed strain) has lost meaning.
inline constexpr double kMaxResultStrain = 10.0 * kMaxStrain;
/// Increments per leg: a million take seconds and write a 200 MB CSV; more is a mistake.
inline constexpr int kMaxIncrements = 1'000'000;
/// p_initial, Pa: from 1 Pa (the weight of 0.1 mm of soil; below it E·Δε swamps p in round-off, see
/// limits::kMaxYoungModulus) to limits::kMaxStress.
inline Range p_initial() {
  return Range::closed(1.0, limits::kMaxStress);
}
/// OCR: p_c0 = OCR · p_initial, and as in the verification case files.
inline Range ocr() {
  return Range::closed_open(1.0, 1e6);
}
inline Range strain() {
  return Range::open(-kMaxStrain, kMaxStrain);
}
/// Driver sub-steps' relative tolerance when on (0 is off): below 1e-12 round-off of the stresses
/// dominates the step-doubling estimate; above 1e-2 the control would accept visibly wrong paths.
inline Range path_tolerance() {
  return Range::closed(1e-12, 1e-2);
}
}  // namespace point_limits

/// The laboratory paths the driver knows (see paths/load_path.h for what each imposes).
enum class LoadPath { TriaxialDrained, TriaxialUndrained, Oedometer, Isotropic, StrainPath };

/// One test: path, initial state and loading programme.
struct PointTest {
  LoadPath path = LoadPath::TriaxialDrained;
  double p_initial = 100e3;                    ///< Pa, initial isotropic effective stress
  double ocr = 1.0;                            ///< MCC: p_c0 = ocr * p_initial
  std::vector<double> strain_targets = {0.1};  ///< targets of the driven strain, compression-positive
                                               ///< (axial for triaxial/oedometer, volumetric for isotropic)
  int increments = 100;                        ///< increments per leg
  std::vector<Mat3> strain_increments;         ///< StrainPath only: tension-positive increments
  /// StrainPath only, optional: where each increment was read ("FILE:LINE"), to name it in messages.
  std::vector<std::string> strain_increment_sources;
  /// Driver sub-steps of mixed-control increments (Programme::path_tolerance): 0 = off.
  double path_tolerance = 0.0;
};

/// One row per increment including the initial state; compression-positive, SI.
/// eps_q = 2/3 (eps_a − eps_r); q = √(3 J2) with the sign of sig_a − sig_r (so q = sig_a − sig_r
/// on axisymmetric states, negative in triaxial extension); p_c = 0 for models without one;
/// u = excess pore pressure of undrained legs, 0 on drained ones; tau_xy = −σ_xy and
/// gamma_xy = −2 ε_xy (the shear components of the compression-positive tensors).
struct PointRecord {
  double eps_a, eps_r, eps_v, eps_q, sig_a, sig_r, p, q, p_c, u, tau_xy, gamma_xy;
};
using PointCurve = std::vector<PointRecord>;


/// `integrator` is "cvode" (the reference) or any name accepted by parse_integrator().
/// Throws std::invalid_argument for an invalid test (outside point_limits) or integrator name, and
/// std::runtime_error naming the increment (describe_increment()) when one cannot be solved or when
/// a result has lost meaning: a non-finite value, |stress| or p_c above limits::kMaxStress, or
/// |strain| above point_limits::kMaxResultStrain.
PointCurve run_point_test(const Material& material, const PointTest& test, std::string_view integrator);

/// CSV with a '#' header comment line (conventions/units), then `comments` each as a '#' line
/// (provenance: version, command, material, ...), then the column row
/// eps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u (more columns may follow).
void write_point_csv(std::ostream& out, const PointCurve& curve, std::span<const std::string> comments = {});

/// The test in one line for a CSV's provenance: "PATH; p_initial = ... Pa; ocr = ...; LOADING",
/// where LOADING is the strain targets with their increments, or `strain_path_file` and its rows.
std::string describe_test(const PointTest& test, std::string_view strain_path_file = "");

/// "triaxial-drained", "triaxial-undrained", "oedometer", "isotropic", "strain-path";
/// throws std::invalid_argument otherwise.
LoadPath parse_load_path(std::string_view name);
/// The name parse_load_path() accepts for `path`.
std::string_view load_path_name(LoadPath path);
/// The integrator name of the CVODE reference.
inline constexpr std::string_view kReferenceIntegrator = "cvode";

}  // namespace soilsph::verification
