// The run does not depend on the order the particles are stored in, only on their positions and
// ids: the soil of a quarter column stored in a shuffled order gives, particle by particle (matched
// by id), the same positions, velocities and stresses bit for bit. A distributed run
// (docs/method/mpi-design.md) stores each rank's particles in an order of its own; this is the
// property its results rest on. It holds because every stage gathers over a particle's row and the
// search lists a row's neighbours in cell order, then by id within a cell.
#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "sph/collapse_3d.h"

using namespace soilsph::sph;

namespace {
const std::string kColumn = std::string(SOILSPH_SOURCE_DIR) + "/data/scenes/axisymmetric-column.toml";

/// `p` with its soil particles stored in the order `order` (soil index k holds the old
/// order[k]); the ghosts keep their places.
ParticlesOf<3> with_soil_order(const ParticlesOf<3>& p, const std::vector<std::size_t>& order) {
  ParticlesOf<3> q = p;
  const auto permute = [&](auto& to, const auto& from) {
    for (std::size_t k = 0; k < order.size(); ++k) to[k] = from[order[k]];
  };
  std::size_t a = 0;
  std::vector<const std::vector<double>*> from;
  p.for_each_array([&](const char*, const std::vector<double>& v) { from.push_back(&v); });
  q.for_each_array([&](const char*, std::vector<double>& v) { permute(v, *from[a++]); });
  permute(q.momentum_source, p.momentum_source);
  permute(q.state, p.state);
  permute(q.layer, p.layer);
  permute(q.material, p.material);
  permute(q.id, p.id);
  return q;
}

/// The soil particles of `p` sorted by id.
std::vector<std::size_t> by_id(const ParticlesOf<3>& p) {
  std::vector<std::size_t> order(p.soil_count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  return order;
}
}  // namespace

TEST_CASE("a 3D run is the same whatever order its soil particles are stored in", "[sph3d][order]") {
  const Scene3 scene = load_scene_3d(
      kColumn, std::vector<std::string>{"scene.particle_spacing=0.02", "scene.end_time=0.03",
                                        "output.frame_interval=0.01", "scene.stop_at_rest=false"});
  Collapse3 stored_as_built(scene);
  std::vector<std::size_t> shuffled(stored_as_built.particles().soil_count);
  std::iota(shuffled.begin(), shuffled.end(), std::size_t{0});
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(20261205));
  Collapse3 stored_shuffled(scene, with_soil_order(stored_as_built.particles(), shuffled));
  REQUIRE(stored_shuffled.particles().id != stored_as_built.particles().id);

  const RunStatistics a = stored_as_built.run(ThreadTuner(1, false));
  const RunStatistics b = stored_shuffled.run(ThreadTuner(1, false));
  REQUIRE(a.steps == b.steps);
  REQUIRE(a.steps > 50);

  const ParticlesOf<3>& p = stored_as_built.particles();
  const ParticlesOf<3>& q = stored_shuffled.particles();
  const std::vector<std::size_t> pi = by_id(p), qi = by_id(q);
  std::size_t different = 0;
  for (std::size_t k = 0; k < pi.size(); ++k) {
    const std::size_t i = pi[k], j = qi[k];
    REQUIRE(p.id[i] == q.id[j]);
    const bool same = p.x[i] == q.x[j] && p.y[i] == q.y[j] && p.z[i] == q.z[j] && p.vx[i] == q.vx[j] &&
                      p.vy[i] == q.vy[j] && p.vz[i] == q.vz[j] && p.density[i] == q.density[j] &&
                      p.sxx[i] == q.sxx[j] && p.syy[i] == q.syy[j] && p.szz[i] == q.szz[j] &&
                      p.sxy[i] == q.sxy[j] && p.sxz[i] == q.sxz[j] && p.syz[i] == q.syz[j];
    different += !same;
  }
  CHECK(different == 0);
  // The particles did move: the comparison is not of two columns at rest.
  double largest_move = 0.0;
  for (std::size_t i = 0; i < p.soil_count; ++i)
    largest_move = std::max(largest_move, std::abs(p.y[i] - p.y0[i]));
  CHECK(largest_move > 1e-4);
}
