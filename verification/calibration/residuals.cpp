#include "verification/calibration/residuals.h"

#include <gsl/gsl_interp.h>
#include <algorithm>
#include <cmath>
#include <memory>

#include "constitutive/parameters.h"
#include "verification/calibration/point_columns.h"

namespace soilsph::calibration {

namespace {

/// The integrator a material names (linear elasticity has none: every scheme is its elastic update).
std::string integrator_of(const Material& material) {
  return std::visit(
      [](const auto& model) -> std::string {
        if constexpr (requires { model.integrator(); })
          return std::string(integrator_name(model.integrator()));
        else
          return "implicit";
      },
      material);
}

std::vector<double> column_of(const verification::PointCurve& curve, std::string_view name) {
  const auto field = point_column(name)->field;
  std::vector<double> values;
  values.reserve(curve.size());
  for (const verification::PointRecord& r : curve) values.push_back(r.*field);
  return values;
}

/// y(x) of the run at each measured x, linearly between its increments (gsl_interp_linear; the
/// run's x must be strictly monotonic and cover the readings).
ModelCurve interpolated(const verification::PointCurve& run, const MeasuredCurve& data,
                        const std::string& where) {
  std::vector<double> x = column_of(run, data.against);
  const bool decreasing = x.size() > 1 && x.back() < x.front();
  const auto ordered = [decreasing](std::vector<double> v) {
    if (decreasing) std::reverse(v.begin(), v.end());
    return v;
  };
  x = ordered(std::move(x));
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1]))
      throw RunError(where + ": the run's " + data.against + " is not strictly monotonic (" +
                     format_number(x[i - 1]) + " then " + format_number(x[i]) +
                     "), so the readings cannot be placed on it; drive the programme in one direction");
  // Readings at the run's ends may differ from its own values by round-off (a stress target
  // reached by Newton to its tolerance): those within 1e-9 of the run's span are taken as at the end.
  const double slack = 1e-9 * (x.back() - x.front());
  const auto [low, high] = std::minmax_element(data.driven.begin(), data.driven.end());
  if (*low < x.front() - slack || *high > x.back() + slack)
    throw RunError(where + ": the readings' " + data.against + " from " + format_number(*low) + " to " +
                   format_number(*high) + " go beyond the run's, " + format_number(x.front()) + " to " +
                   format_number(x.back()));
  const std::unique_ptr<gsl_interp, decltype(&gsl_interp_free)> interp(
      gsl_interp_alloc(gsl_interp_linear, x.size()), gsl_interp_free);
  ModelCurve model;
  for (const std::string& name : data.names) {
    const std::vector<double> y = ordered(column_of(run, name));
    gsl_interp_init(interp.get(), x.data(), y.data(), x.size());
    std::vector<double>& out = model.columns.emplace_back();
    for (const double xi : data.driven)
      out.push_back(
          gsl_interp_eval(interp.get(), x.data(), y.data(), std::clamp(xi, x.front(), x.back()), nullptr));
  }
  return model;
}

}  // namespace

verification::PointCurve run_experiment(const Experiment& e, const toml::table& material) {
  const verification::ProgrammeFile programme = experiment_programme(e, material);
  return verification::run_programme(programme.material, programme.programme,
                                     integrator_of(programme.material));
}

Residuals::Residuals(const CalibrationFile& file) : file_(file) {
  for (const Experiment& e : file.experiments) {
    std::vector<double>& ranges = ranges_.emplace_back();
    for (std::size_t c = 0; c < e.data.names.size(); ++c) {
      const auto [low, high] = std::minmax_element(e.data.columns[c].begin(), e.data.columns[c].end());
      if (!(*high > *low))
        throw ParameterError(e.data.path + ": column " + e.data.names[c] + " has the same value " +
                             format_number(*low) + " in every reading, so it has no range to normalise by (" +
                             e.where + " match)");
      ranges.push_back(*high - *low);
      size_ += e.data.driven.size();
    }
  }
}

std::vector<ModelCurve> Residuals::curves(std::span<const double> values) const {
  toml::table material;
  try {
    material = file_.material.with(values);
    file_.material.build(values);  // the factory's checks, said of the material
  } catch (const ParameterError& e) {
    throw RunError(std::string("the model refuses the parameters: ") + e.what());
  }
  std::vector<ModelCurve> curves;
  for (const Experiment& e : file_.experiments) {
    try {
      curves.push_back(interpolated(run_experiment(e, material), e.data, e.where));
    } catch (const RunError&) {
      throw;
    } catch (const std::exception& error) {  // the driver's or the programme's own message
      throw RunError(e.where + ": " + error.what());
    }
  }
  return curves;
}

Eigen::VectorXd Residuals::operator()(std::span<const double> values) const {
  const std::vector<ModelCurve> model = curves(values);
  Eigen::VectorXd r(static_cast<Eigen::Index>(size_));
  Eigen::Index i = 0;
  for (std::size_t e = 0; e < file_.experiments.size(); ++e) {
    const Experiment& experiment = file_.experiments[e];
    const double weight = std::sqrt(experiment.weight);
    for (std::size_t c = 0; c < experiment.data.names.size(); ++c)
      for (std::size_t k = 0; k < experiment.data.driven.size(); ++k)
        r(i++) = weight * (model[e].columns[c][k] - experiment.data.columns[c][k]) / ranges_[e][c];
  }
  return r;
}

}  // namespace soilsph::calibration
