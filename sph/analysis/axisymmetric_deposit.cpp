#include "sph/analysis/axisymmetric_deposit.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "sph/analysis/deposit.h"

namespace soilsph::sph {

namespace {
/// The last value of `sorted` (in the order given) reached from its first without a gap wider than
/// `gap`: the body's edge, splashed particles beyond left out.
double last_linked(const std::vector<double>& sorted, double gap) {
  std::size_t k = 0;
  while (k + 1 < sorted.size() && std::abs(sorted[k + 1] - sorted[k]) <= gap) ++k;
  return sorted[k];
}

/// The top (height, radius) of a strip's soil held up from the floor: sorted by height, from the
/// lowest (within `link` of the floor, else the strip holds only splashed grains and has no top)
/// up to the first gap wider than `link`. A grain in the air over the strip is not its top.
std::optional<std::pair<double, double>> linked_top(std::vector<std::pair<double, double>>& strip,
                                                    double link) {
  std::sort(strip.begin(), strip.end());
  if (strip.front().first > link) return std::nullopt;
  std::size_t k = 0;
  while (k + 1 < strip.size() && strip[k + 1].first - strip[k].first <= link) ++k;
  return strip[k];
}
}  // namespace

AxisymmetricDeposit measure_axisymmetric_deposit(std::span<const Vec3> soil, const DepositAxis& axis,
                                                 double dx, double span_deg, int sectors,
                                                 double toe_thickness) {
  if (soil.empty()) throw std::invalid_argument("axisymmetric deposit: no particle");
  if (!(dx > 0.0)) throw std::invalid_argument("axisymmetric deposit: the spacing must be positive");
  if (!(span_deg > 0.0 && span_deg <= 360.0))
    throw std::invalid_argument("axisymmetric deposit: the azimuth span must lie in (0, 360] degrees");
  if (sectors < 1) throw std::invalid_argument("axisymmetric deposit: at least one sector");
  const double link = deposit_link_spacings * dx, span = span_deg * std::numbers::pi / 180.0;
  std::vector<std::vector<double>> radii(static_cast<std::size_t>(sectors));
  // Per sector, each radial strip of width dx: strip → its particles' (height, radius).
  std::vector<std::map<long long, std::vector<std::pair<double, double>>>> strips(
      static_cast<std::size_t>(sectors));
  std::vector<double> axis_heights;
  for (const Vec3& p : soil) {
    const Vec3 d = p - axis.point;
    const double height = dot(d, axis.up), x = dot(d, axis.azimuth_zero), y = dot(d, axis.azimuth_quarter);
    const double radius = std::hypot(x, y);
    if (radius <= 2.0 * dx) axis_heights.push_back(height);
    double azimuth = std::atan2(y, x);
    if (azimuth < 0.0) azimuth += 2.0 * std::numbers::pi;
    // A particle on the axis, or at an azimuth the span leaves out (beyond a symmetry plane by
    // round-off), goes to the nearest sector.
    if (azimuth > span) azimuth = azimuth - span < 2.0 * std::numbers::pi - azimuth ? span : 0.0;
    const auto sector = std::min(static_cast<std::size_t>(azimuth / span * sectors), radii.size() - 1);
    strips[sector][std::llround(radius / dx)].emplace_back(height, radius);
    if (height <= bottom_layer_spacings * dx) radii[sector].push_back(radius);
  }
  AxisymmetricDeposit deposit{};
  for (std::vector<double>& r : radii) {
    std::sort(r.begin(), r.end(), std::greater<>());
    // From the farthest inwards: drop particles while the next one inwards is more than `link` away.
    std::size_t k = 0;
    while (k + 1 < r.size() && r[k] - r[k + 1] > link) ++k;
    deposit.sector_runout_m.push_back(r.empty() ? 0.0 : r[k]);
  }
  const auto [low, high] =
      std::minmax_element(deposit.sector_runout_m.begin(), deposit.sector_runout_m.end());
  double sum = 0.0;
  for (const double r : deposit.sector_runout_m) sum += r;
  deposit.runout_radius_m = sum / sectors;
  deposit.runout_radius_spread_m = *high - *low;
  deposit.runout_radius_thick_m = std::numeric_limits<double>::quiet_NaN();
  if (toe_thickness > 0.0) {
    double thick = 0.0;
    for (auto& sector_strips : strips) {
      // From the outermost strip inwards, the first whose cell top reaches the toe thickness.
      for (auto strip = sector_strips.rbegin(); strip != sector_strips.rend(); ++strip) {
        const std::optional<std::pair<double, double>> top = linked_top(strip->second, link);
        if (top && top->first + 0.5 * dx >= toe_thickness) {
          thick += top->second;
          break;
        }
      }
    }
    deposit.runout_radius_thick_m = thick / sectors;
  }
  std::sort(axis_heights.begin(), axis_heights.end());
  deposit.height_m =
      axis_heights.empty() || axis_heights.front() > link ? 0.0 : last_linked(axis_heights, link) + 0.5 * dx;
  return deposit;
}

namespace lube2004 {
double runout_ratio(double a) {
  return a <= 1.7 ? 1.24 * a : 1.6 * std::sqrt(a);
}
double height_ratio(double a) {
  return std::min(a, 0.88 * std::pow(a, 1.0 / 6.0));
}
double time_to_rest(double column_height, double gravity) {
  return 3.0 * std::sqrt(column_height / gravity);
}
}  // namespace lube2004

}  // namespace soilsph::sph
