#include "verification/closed_form/closed_form.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "verification/closed_form/cam_clay_compression.h"
#include "verification/closed_form/cam_clay_drained.h"
#include "verification/closed_form/cam_clay_undrained.h"
#include "verification/closed_form/drucker_prager_triaxial.h"

namespace soilsph::verification {

namespace {
void require(bool ok, std::string_view name, std::string_view what) {
  if (!ok) throw std::invalid_argument("closed form '" + std::string(name) + "': " + std::string(what));
}

template <class Model>
const Model& model_of(const Material& material, std::string_view name) {
  const Model* model = std::get_if<Model>(&material);
  require(model != nullptr, name, "applies to " + std::string(Model::kName) + " only");
  return *model;
}

/// Triaxial closed forms describe one monotonic loading.
void require_monotonic(std::span<const double> driven, std::string_view name) {
  require(std::is_sorted(driven.begin(), driven.end()), name, "needs a single monotonic loading leg");
}

template <class ClosedForm>
std::vector<ReferencePoint> pointwise(const ClosedForm& cf, std::span<const double> driven) {
  std::vector<ReferencePoint> out;
  out.reserve(driven.size());
  for (const double e : driven) out.push_back(cf.at(e));
  return out;
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
  throw std::invalid_argument("unknown closed form '" + std::string(name) + "'");
}

}  // namespace soilsph::verification
