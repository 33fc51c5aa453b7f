#include "verification/closed_form/closed_form.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "verification/closed_form/cam_clay_compression.h"
#include "verification/closed_form/cam_clay_drained.h"
#include "verification/closed_form/cam_clay_undrained.h"
#include "verification/closed_form/drucker_prager_strain_path.h"
#include "verification/closed_form/drucker_prager_triaxial.h"
#include "verification/closed_form/mohr_coulomb_triaxial.h"

namespace soilsph::verification {

namespace {
void require(bool ok, std::string_view name, std::string_view what) {
  if (!ok) throw std::invalid_argument("closed form '" + std::string(name) + "': " + std::string(what));
}

template <class Model>
const Model& model_of(const Material& material, std::string_view name) {
  const Model* model = std::get_if<Model>(&material);
  require(model != nullptr, name, "applies to " + std::string(Model::kName) + " only");
  if constexpr (std::is_same_v<Model, ModifiedCamClay>)
    // The Cam-clay closed forms integrate the hardening with the initial specific volume (eq 27).
    require(!model->hardens_with_current_volume(), name,
            "integrates with the initial specific volume; hardening_volume = \"current\" has no closed form "
            "here (compare it against cvode)");
  return *model;
}

/// Triaxial closed forms describe one monotonic loading.
void require_monotonic(std::span<const double> driven, std::string_view name) {
  require(std::is_sorted(driven.begin(), driven.end()), name, "needs a single monotonic loading leg");
}

template <class ClosedForm>
std::vector<ReferencePoint> pointwise(const ClosedForm& cf, std::span<const double> driven,
                                      double scale = 1.0) {
  std::vector<ReferencePoint> out;
  out.reserve(driven.size());
  for (const double e : driven) out.push_back(cf.at(scale * e));
  return out;
}

/// D-P under a fixed-ratio strain path: linear branches, so any programme that stays elastic is
/// described, and a monotonic one beyond yield. `axial_per_driven` converts the driven strain to ε_a.
std::vector<ReferencePoint> drucker_prager_strain_path(const DruckerPrager& model, const PointTest& test,
                                                       std::span<const double> driven, std::string_view name,
                                                       double volume_ratio, double shear_ratio,
                                                       double axial_per_driven) {
  const DruckerPragerStrainPath cf(model, test.p_initial, volume_ratio, shear_ratio);
  const bool elastic = std::all_of(driven.begin(), driven.end(),
                                   [&](double e) { return axial_per_driven * e <= cf.yield_strain(); });
  if (!elastic) require_monotonic(driven, name);
  return pointwise(cf, driven, axial_per_driven);
}
}  // namespace

double driven_strain(const PointRecord& row, LoadPath path) {
  return path == LoadPath::Isotropic ? row.eps_v : row.eps_a;
}

std::vector<ReferencePoint> closed_form_curve(std::string_view name, const Material& material,
                                              const PointTest& test, std::span<const double> driven) {
  const auto needs_path = [&](LoadPath path) {
    require(test.path == path, name, "applies to the " + std::string(load_path_name(path)) + " path only");
  };
  if (name == "dp-triaxial-drained") {
    needs_path(LoadPath::TriaxialDrained);
    require_monotonic(driven, name);
    return pointwise(DruckerPragerDrainedTriaxial(model_of<DruckerPrager>(material, name), test.p_initial),
                     driven);
  }
  if (name == "dp-triaxial-undrained") {
    needs_path(LoadPath::TriaxialUndrained);
    return drucker_prager_strain_path(model_of<DruckerPrager>(material, name), test, driven, name, 0.0, 1.0,
                                      1.0);
  }
  if (name == "dp-oedometer") {
    needs_path(LoadPath::Oedometer);
    return drucker_prager_strain_path(model_of<DruckerPrager>(material, name), test, driven, name, 1.0,
                                      2.0 / 3.0, 1.0);
  }
  if (name == "dp-isotropic") {  // driven ε_v = 3 ε_a
    needs_path(LoadPath::Isotropic);
    return drucker_prager_strain_path(model_of<DruckerPrager>(material, name), test, driven, name, 3.0, 0.0,
                                      1.0 / 3.0);
  }
  if (name == "mcc-triaxial-undrained") {
    needs_path(LoadPath::TriaxialUndrained);
    require_monotonic(driven, name);
    return pointwise(
        CamClayUndrainedTriaxial(model_of<ModifiedCamClay>(material, name), test.p_initial, test.ocr),
        driven);
  }
  if (name == "mcc-triaxial-drained") {
    needs_path(LoadPath::TriaxialDrained);
    require_monotonic(driven, name);
    return pointwise(
        CamClayDrainedTriaxial(model_of<ModifiedCamClay>(material, name), test.p_initial, test.ocr), driven);
  }
  if (name == "mcc-isotropic") {
    needs_path(LoadPath::Isotropic);
    return CamClayIsotropicCompression(model_of<ModifiedCamClay>(material, name), test.p_initial, test.ocr)
        .curve(driven);
  }
  if (name == "mcc-oedometer") {
    needs_path(LoadPath::Oedometer);
    return CamClayOedometer(model_of<ModifiedCamClay>(material, name), test.p_initial, test.ocr)
        .curve(driven);
  }
  if (name == "mc-triaxial-drained" || name == "mc-triaxial-undrained") {  // compression or extension
    const bool undrained = name == "mc-triaxial-undrained";
    needs_path(undrained ? LoadPath::TriaxialUndrained : LoadPath::TriaxialDrained);
    require(std::is_sorted(driven.begin(), driven.end()) || std::is_sorted(driven.rbegin(), driven.rend()), name,
            "needs a single monotonic loading leg");
    return pointwise(MohrCoulombTriaxial(model_of<MohrCoulomb>(material, name), test.p_initial, undrained), driven);
  }
  throw std::invalid_argument("unknown closed form '" + std::string(name) + "'");
}

}  // namespace soilsph::verification
