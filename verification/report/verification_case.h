#pragma once
/// @file
/// Verification cases as data: each `[[case]]` of a `verification/cases/*.toml` file names a material
/// file, a load path and its programme, the closed form to compare with, and the integrators to run
/// with the tolerance each must meet (`tolerance = { cvode = 1e-5, explicit = 2e-2 }`): adding an
/// integrator to the report is a TOML edit. A case of a UMAT plug-in (`model = "umat"`) runs its own
/// update, labelled "umat" (`tolerance = { umat = 1e-8 }`; no CVODE reference: a UMAT exposes no
/// rate equations), and takes the closed form's parameters from `closed_form_material`, the built-in
/// model the plug-in claims to be. Every key is validated; errors name the file, the case and the key.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "verification/point_test.h"

namespace soilsph::verification {

struct VerificationCase {
  std::string name;           ///< unique, used for file names
  std::string source;         ///< the case file
  std::string material_file;  ///< resolved path of the material file
  Material material;
  PointTest test;
  std::string closed_form = "none";  ///< a name of kClosedFormNames
  /// (integrator, maximum relative error allowed), in file order; "cvode" is the reference, "umat"
  /// a UMAT plug-in's own update.
  std::vector<std::pair<std::string, double>> tolerances;
  /// A UMAT case's built-in material whose closed form the plug-in must follow (closed_form_material).
  std::optional<Material> closed_form_material;

  /// The material whose parameters the closed form takes.
  const Material& closed_form_source() const {
    return closed_form_material ? *closed_form_material : material;
  }
};

/// The run label of a UMAT plug-in's own update in a case's tolerances and in the report.
inline constexpr std::string_view kUmatRun = "umat";

/// The cases of one file; material paths are relative to the case file's folder.
std::vector<VerificationCase> read_case_file(const std::filesystem::path& file);
/// The cases of every `*.toml` file in `folder` (sorted by file name), or of `folder` if it is a
/// file; throws ParameterError when there is none or when two cases share a name.
std::vector<VerificationCase> read_cases(const std::filesystem::path& folder);

}  // namespace soilsph::verification
