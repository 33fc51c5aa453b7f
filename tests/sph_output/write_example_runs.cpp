// Two synthetic "collapse" runs written with the real writers, for the Python checks of the files and
// the pictures (ctest fixture sph_output_runs). The motion is a prescribed smooth deformation of the
// paper's 41 × 61 column, not physics: it only has to look like a collapse and be known exactly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "sph/analysis/deposit.h"
#include "sph/output/frame_writer.h"
#include "sph/output/summary.h"

using namespace soilsph::sph;

namespace {

constexpr double kWidth = 0.04, kHeight = 0.06, kSpacing = 1e-3, kDuration = 0.25, kDensity = 2000.0;
constexpr double kGravity = 9.81, kK0 = 0.5;

/// Writes DIR with frames every 0.01 s: particle (x0, y0), at distance ξ = (W − x0)/W from the wall
/// and height η = y0/H, ends at x = W − W ξ (1 + spread (1 − η)), y = H η (1 − slump ξ), moved along
/// the smooth ramp s(τ) = 3τ² − 2τ³ (τ = t/T), so the bottom row's runout is W (1 + spread).
void write_run(const std::filesystem::path& dir, const std::string& model, double spread, double slump) {
  std::vector<double> x0, y0;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 60; ++j) {
      x0.push_back(i * kSpacing);
      y0.push_back(j * kSpacing);
    }
  }
  const std::size_t n = x0.size();
  std::vector<double> xf(n), yf(n), x(n), y(n), vx(n), vy(n), sxx(n), syy(n), szz(n), sxy(n, 0.0), p(n), q(n),
      eps(n), density(n, kDensity);
  std::vector<int> layer(n), material(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double xi = (kWidth - x0[i]) / kWidth, eta = y0[i] / kHeight;
    xf[i] = kWidth - kWidth * xi * (1 + spread * (1 - eta));
    yf[i] = kHeight * eta * (1 - slump * xi);
    layer[i] = static_cast<int>(std::floor(y0[i] / 0.01 + 1e-9));  // 1 cm layers from the bottom
  }
  FrameWriter writer(dir);
  for (int frame = 0; frame <= 25; ++frame) {
    const double t = 0.01 * frame, tau = t / kDuration;
    const double s = tau * tau * (3 - 2 * tau), ds = 6 * tau * (1 - tau) / kDuration;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = x0[i] + s * (xf[i] - x0[i]);
      y[i] = y0[i] + s * (yf[i] - y0[i]);
      vx[i] = ds * (xf[i] - x0[i]);
      vy[i] = ds * (yf[i] - y0[i]);
      // Geostatic stress under the column's initial top (tension-positive) and its invariants.
      syy[i] = -kDensity * kGravity * (kHeight - y[i]);
      sxx[i] = szz[i] = kK0 * syy[i];
      p[i] = -(sxx[i] + syy[i] + szz[i]) / 3;
      q[i] = std::abs(syy[i] - sxx[i]);  // axisymmetric about y: q = |σ_yy − σ_xx|
      eps[i] = s * spread * (1 - y0[i] / kHeight);
    }
    writer.write({t, x, y, vx, vy, sxx, syy, szz, sxy, p, q, eps, density, layer, material});
  }
  const DepositMetrics deposit = measure_deposit(x, y, kWidth, kSpacing);
  CHECK(deposit.runout_m == Approx(kWidth * (1 + spread)).epsilon(1e-12));
  CHECK(deposit.height_m == Approx(kHeight).epsilon(1e-12));

  Summary summary;
  summary.model = model;
  summary.integrator = "explicit";
  summary.particles = n;
  summary.boundary_particles = 1132;
  summary.steps = 25;
  summary.end_time = kDuration;
  summary.runout_m = deposit.runout_m;
  summary.height_m = deposit.height_m;
  summary.repose_angle_deg = deposit.repose_angle_deg;
  summary.particle_spacing = kSpacing;
  summary.smoothing_ratio = 1.2;
  summary.time_step = 0.01;
  summary.complete = true;
  summary.stop_reason = "end time";
  write_summary_json(dir / "summary.json", summary);
}

}  // namespace

TEST_CASE("write two synthetic runs for the file and picture checks", "[.][example_runs]") {
  const std::filesystem::path root = SOILSPH_EXAMPLE_RUNS_DIR;
  std::filesystem::remove_all(root);
  write_run(root / "dp", "drucker-prager", 2.0, 0.8);
  write_run(root / "mcc", "modified-cam-clay", 1.5, 0.7);
}
