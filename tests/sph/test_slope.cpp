// The slope of data/scenes/slope.toml by strength reduction at a coarse spacing:
// with its full strength it stands, with c and tan(phi) divided by twice its limit-equilibrium factor
// of safety it fails. FoS_Bishop = 1.53 (scripts/slope_bishop.py, checked in ctest slope_bishop.check).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "helpers.h"
#include "sph/diagnostics.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;

namespace {
constexpr double kFosBishop = 1.53;  // scripts/slope_bishop.py data/scenes/slope.toml: 1.5299

/// The largest displacement of a soil particle after the slope with Mohr-Coulomb strength reduced
/// by `factor` (c/F, tan(phi)/F) has run to `end_time` at 4 mm.
double largest_displacement(double factor, double end_time) {
  const double c = 48.0 / factor, phi = std::atan(std::tan(25.0 * M_PI / 180.0) / factor) * 180.0 / M_PI;
  const Scene scene = test::shipped_scene(
      "slope", {"scene.particle_spacing=0.004", "scene.end_time=" + std::to_string(end_time),
                "material.cohesion=" + std::to_string(c), "material.friction_angle=" + std::to_string(phi)});
  Particles p = build_particles(scene);
  set_geostatic_state(p, scene);
  const std::vector<double> x0(p.x.begin(), p.x.begin() + static_cast<std::ptrdiff_t>(p.soil_count));
  const std::vector<double> y0(p.y.begin(), p.y.begin() + static_cast<std::ptrdiff_t>(p.soil_count));
  const SolverSetup setup = make_solver_setup(scene);
  std::visit([&](const auto& model) { run(model, setup, p, [](const Particles&, double) {}, [](double, std::size_t) {}); },
             scene.material);
  REQUIRE(all_finite(p));
  double largest = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i) largest = std::max(largest, std::hypot(p.x[i] - x0[i], p.y[i] - y0[i]));
  return largest;
}
}  // namespace

TEST_CASE("the slope stands at full strength and fails at twice its Bishop factor of safety", "[slope]") {
  const double dx = 0.004;
  CHECK(largest_displacement(1.0, 0.3) < 0.5 * dx);
  CHECK(largest_displacement(2.0 * kFosBishop, 0.3) > 3.0 * dx);
}
