// [numerics] kernel: a scene chooses the cubic spline (the default, the paper's) or the Wendland C2
// kernel; the key is validated and recorded in the scene as run, and a step's pair rows hold the
// chosen kernel's W and dW/dr / r (the solver picks the shape once, outside its loops).
#include <catch2/catch.hpp>

#include "../common/pair_rows.h"
#include "helpers.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

TEST_CASE("[numerics] kernel: the cubic spline by default, the Wendland C2 kernel on request, nothing else",
          "[scene][kernel]") {
  const Scene plain = sph::test::shipped_scene("collapse-dp");
  CHECK(plain.numerics.kernel == KernelShape::CubicSpline);
  CHECK(plain.resolved["numerics"]["kernel"].value<std::string>() == "cubic-spline");
  const Scene wendland = sph::test::shipped_scene("collapse-dp", {"numerics.kernel=\"wendland-c2\""});
  CHECK(wendland.numerics.kernel == KernelShape::WendlandC2);
  CHECK(wendland.resolved["numerics"]["kernel"].value<std::string>() == "wendland-c2");
  CHECK(make_solver_setup(wendland).kernel.shape() == KernelShape::WendlandC2);
  CHECK_THROWS_WITH(sph::test::shipped_scene("collapse-dp", {"numerics.kernel=\"quintic\""}),
                    Contains("[numerics] kernel") && Contains("\"cubic-spline\", \"wendland-c2\""));
  CHECK_THROWS_WITH(sph::test::shipped_scene("collapse-dp", {"numerics.kernel=2"}),
                    Contains("[numerics] kernel"));
}

TEST_CASE("a step's pair rows hold the scene's kernel, soil and ghost rows alike", "[kernel][leapfrog]") {
  for (const KernelShape shape : {KernelShape::CubicSpline, KernelShape::WendlandC2}) {
    const bool wendland = shape == KernelShape::WendlandC2;
    CAPTURE(wendland);
    const Scene scene = sph::test::shipped_scene(
        "collapse-dp",
        {"scene.particle_spacing=0.004",
         std::string("numerics.kernel=") + (wendland ? "\"wendland-c2\"" : "\"cubic-spline\"")});
    Particles p = build_particles(scene);
    set_geostatic_state(p, scene);
    const SolverSetup setup = make_solver_setup(scene);
    const Particles at_start = p;
    Workspace work(setup, p);
    advance(std::get<DruckerPrager>(scene.material), setup, p, work, setup.initial_time_step());
    const double h = setup.kernel.smoothing_length();
    const PairList<2>& rows = work.pairs.neighbours;
    std::size_t ghost_pairs = 0;
    for (std::size_t b = p.soil_count; b < p.size(); ++b) ghost_pairs += rows.pair_count(b);
    REQUIRE(rows.pair_count(0) > 0);
    REQUIRE(ghost_pairs > 0);
    const auto difference = [&](const auto& kernel) {
      return soilsph::test::largest_row_difference(rows, at_start, kernel);
    };
    const double to_cubic = difference(CubicSplineKernel<2>(h)), to_wendland = difference(WendlandC2Kernel<2>(h));
    CHECK((wendland ? to_wendland : to_cubic) < 1e-12);
    CHECK((wendland ? to_cubic : to_wendland) > 0.1);  // the two shapes differ by more than that over a row
  }
}
