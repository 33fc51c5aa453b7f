#include "verification/tangent_check.h"

#include "constitutive/tangent.h"
#include "verification/driver/mixed_control.h"

namespace soilsph::verification {

namespace {
/// The tangent the model hands a Newton iteration: a UMAT's DDSDDE as returned, else the
/// algorithmic tangent (constitutive/tangent.h).
template <class Model>
Mat6 returned_tangent(const Model& model, const State& state, const Mat3& strain_increment) {
  if constexpr (requires { model.returned_tangent(state, strain_increment); })
    return model.returned_tangent(state, strain_increment);
  else
    return algorithmic_tangent(model, state, strain_increment);
}
}  // namespace

std::vector<TangentCheckRow> check_tangent(const Material& material, const Programme& programme) {
  return std::visit(
      [&](const auto& model) {
        const PointHistory history = drive_mixed_control(model, programme.initial, programme.legs);
        std::vector<TangentCheckRow> rows;
        for (std::size_t k = 0; k + 1 < history.size(); ++k) {
          const State& state = history[k].state;
          const Mat3 increment = history[k + 1].strain - history[k].strain;
          const Mat6 returned = returned_tangent(model, state, increment);
          const Mat6 differences = finite_difference_tangent(model, state, increment);
          const double scale =
              std::max(differences.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
          rows.push_back({static_cast<int>(k + 1), (returned - differences).cwiseAbs() / scale});
        }
        return rows;
      },
      material);
}

}  // namespace soilsph::verification
