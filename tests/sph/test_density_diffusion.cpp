// [numerics] density_diffusion: δ of eq 11's δ-SPH term (stages/continuity.h). Off by default (eq 11
// as printed); the solver takes δ h c with the scene's h and initial sound speed; δ × cfl beyond the
// diffusion's stability is refused, naming the key.
#include <catch2/catch.hpp>

#include "helpers.h"
#include "sph/solver.h"

using namespace soilsph;
using namespace soilsph::sph;
using Catch::Matchers::Contains;

TEST_CASE("[numerics] density_diffusion: off by default, δ h c in the solver, δ × cfl bounded", "[scene]") {
  const Scene plain = sph::test::shipped_scene("collapse-dp");
  CHECK(plain.numerics.density_diffusion == 0.0);
  CHECK(make_solver_setup(plain).kinematics.density_diffusion == 0.0);
  CHECK(plain.resolved["numerics"]["density_diffusion"].value<double>() == 0.0);

  const Scene with = sph::test::shipped_scene("collapse-dp", {"numerics.density_diffusion=0.1"});
  const SolverSetup setup = make_solver_setup(with);
  CHECK(setup.kinematics.density_diffusion ==
        Approx(0.1 * setup.kernel.smoothing_length() * setup.sound_speed).epsilon(1e-12));
  CHECK(with.resolved["numerics"]["density_diffusion"].value<double>() == 0.1);

  CHECK_THROWS_WITH(sph::test::shipped_scene("collapse-dp", {"numerics.density_diffusion=-0.1"}),
                    Contains("[numerics] density_diffusion"));
  CHECK_THROWS_WITH(sph::test::shipped_scene("collapse-dp", {"numerics.density_diffusion=2"}),
                    Contains("[numerics] density_diffusion"));
  // collapse-dp runs at cfl = 1.0: δ = 0.3 is beyond 0.25 / cfl; at cfl = 0.5 it is within.
  CHECK_THROWS_WITH(sph::test::shipped_scene("collapse-dp", {"numerics.density_diffusion=0.3"}),
                    Contains("[numerics] density_diffusion") && Contains("0.25 / cfl"));
  CHECK_NOTHROW(sph::test::shipped_scene("collapse-dp", {"numerics.density_diffusion=0.3", "numerics.cfl=0.5"}));
}
