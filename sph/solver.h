#pragma once
/// @file
/// The time loop of the collapse, in one place. `advance` is one leapfrog step and reads as the
/// algorithm; `run` repeats it until the end time or rest and hands frames to the caller. The soil
/// is one MaterialGroup per material, each a contiguous range of particles: the stress update
/// chooses each group's model once per step (std::visit outside the loop over its particles), so
/// the per-particle update is a direct, inlinable call. The typed `run(model, ...)` and
/// `advance(model, ...)` run the whole soil with one model (tests).
///
/// Threading: `run` opens one OpenMP parallel region per chunk of steps (about 50 ms), with the
/// thread count a ThreadTuner picks for it. A step is four work-shared loops over particles, each
/// fusing every stage that reads the same data (below), plus one short serial close: five barriers
/// a step instead of a fork and a join per stage. A barrier is the only cost of a second thread,
/// and it is what a sleeping (passive) or descheduled thread makes expensive, so the fewer the
/// better on an idle and on a busy machine alike. The soil loops whose cost per particle varies
/// (pairs, acceleration, stress update) are cut by measured cost, not count (range_balancer.h):
/// MCC's plastic returns cluster where the soil yields. Called outside a parallel region (the tests),
/// `advance` does the same work on one thread. Results do not depend on the thread count: every
/// loop writes per particle, reductions are serial.
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sph/blow_up.h"
#include "sph/kernel.h"
#include "sph/neighbours/neighbour_list.h"
#include "sph/particles.h"
#include "sph/range_balancer.h"
#include "sph/rest.h"
#include "sph/scene.h"
#include "sph/scene_3d.h"
#include "sph/stages/artificial_stress.h"
#include "sph/stages/boundaries.h"
#include "sph/stages/continuity.h"
#include "sph/stages/leapfrog.h"
#include "sph/stages/mirror_images.h"
#include "sph/stages/momentum.h"
#include "sph/stages/plane_guard.h"
#include "sph/stages/stress_update.h"
#include "sph/stages/velocity_gradient.h"
#include "sph/thread_tuner.h"
#include "sph/time_step.h"

namespace soilsph::sph {

/// The soil particles [begin, end) of one material, with its model and the model a failed update
/// falls back on (stages/stress_update.h).
struct MaterialGroup {
  Material model, fallback;
  std::size_t begin = 0, end = 0;
  bool pressure_dependent = false;  ///< its stiffness follows the state (MCC's κ, a UMAT's DDSDDE)
};
using MaterialGroups = std::vector<MaterialGroup>;

/// The groups of the soil's materials (Particles::material, contiguous per material).
template <int dim>
MaterialGroups material_groups(const std::vector<Material>& materials, const ParticlesOf<dim>& p);

/// The wall guard of a dimension: the plane's segments, space's planes.
template <int dim>
using WallGuardOf = std::conditional_t<dim == 2, WallGuard, PlaneGuard>;

/// Everything fixed for a run, derived from the scene once.
template <int dim>
struct SolverSetupOf {
  SmoothingKernel<dim> kernel;  ///< the scene's shape ([numerics] kernel) and h
  double cfl;          ///< C in Δt = C h / (c + |v|_max)
  double sound_speed;  ///< c at the start (m/s); also the artificial viscosity's c̄
  double end_time;     ///< s
  double frame_interval;
  MomentumParamsOf<dim> momentum;
  WallGuardOf<dim> guard;
  WallMotionsOf<dim> walls;     ///< moving and removed walls (stages/wall_motions.h)
  double potential_datum = 0.0; ///< height of the lowest wall along −g (m), for the energy budget
  KinematicOptions kinematics{};  ///< eq 23's correction, eq 11's diffusion (stages/velocity_gradient.h)
  bool pressure_dependent_stiffness = false;  ///< recompute c from the pressures at each search
  RestCriterion rest;
  DomainOf<dim> domain;             ///< no soil particle may leave it (blow_up.h)
  double checkpoint_interval = 0.0;  ///< s of simulated time between checkpoints (0: none at intervals)
  double constant_stiffness_sound_speed = 0.0;  ///< the largest c of the materials of constant stiffness
  Vec<dim> ghost_body_force{};  ///< body force per mass the ghosts' normal stress balances (m/s²; 0: none)
  std::vector<SymmetryPlane> symmetry_planes{};  ///< mirrored by the soil's images (stages/mirror_images.h)
  double image_reach = 0.0;  ///< how far from a symmetry plane the soil has images (m; mirror_images.h)

  /// Δt of the soil at rest with the initial sound speed: the largest step the run takes while c
  /// does not fall.
  double initial_time_step() const { return cfl_time_step(cfl, kernel.smoothing_length(), sound_speed); }
};

using SolverSetup = SolverSetupOf<2>;

/// Derives the kernel, the time step and the stage parameters from the scene (sph/solver.cpp).
SolverSetup make_solver_setup(const Scene& scene);
/// The same for a scene of space (sph/solver_3d.cpp, library soilsph_sph_3d).
SolverSetupOf<3> make_solver_setup(const Scene3& scene);

/// The state inside a step at t^n, after the acceleration and before anything changes σ, v or the
/// pairs: what the histories sample (output/history_writer.h; analysis/boundary_forces.h, gauges.h).
template <int dim>
struct StepSampleOf {
  double time;                                   ///< t^n (s)
  const ParticlesOf<dim>& particles;             ///< x^n, σ^n, v^{n−½}
  const PairList<dim>& neighbours;               ///< the pairs at x^n
  const MomentumParamsOf<dim>& momentum;         ///< the parameters of the acceleration just computed
  std::array<std::span<const double>, dim> v_next;  ///< v^{n+½} (vx, vy[, vz])
};
using StepSample = StepSampleOf<2>;

/// The neighbour pairs, and what loop 1 prepares from the particles for the pair sums of the loops
/// after it.
template <int dim>
struct PairDataOf {
  PairList<dim> neighbours;
  std::vector<double> volume;  ///< m/ρ^n of every particle, for eq 23 (one division per particle, not per pair)
  std::atomic<bool> any_tension{false};  ///< a particle carries artificial stress this step (loop 1 → 2)
  bool search_next = true;               ///< the next step searches neighbours (Verlet skin exceeded)

  explicit PairDataOf(std::size_t particles) : volume(particles) {}
};

/// The state at the step's end while the step computes it, kept apart from the state at its start,
/// which the neighbours still read; the step's close swaps it in.
template <int dim>
struct NextStateOf {
  std::array<std::vector<double>, dim> velocity;  ///< v^{n+½}
  std::vector<double> density;                    ///< ρ^{n+1}
  /// x^{n+1}: a pair takes x_i − x_j from the positions (neighbours/neighbour_list.h), which the
  /// drift must not change under the loop that still reads them. The ghosts' entries are brought up
  /// to date only where walls move (close_step).
  std::array<std::vector<double>, dim> position;

  explicit NextStateOf(const ParticlesOf<dim>& p) : density(p.density) {
    const auto v = velocities(p);
    const auto x = p.coordinates();
    for (int a = 0; a < dim; ++a) {
      velocity[a].assign(v[a].begin(), v[a].end());
      position[a].assign(x[a].begin(), x[a].end());
    }
  }
  /// Room for n particles (the soil's mirror images change in number; their entries are written
  /// before they are read).
  void resize(std::size_t n) {
    for (auto& a : velocity) a.resize(n);
    density.resize(n);
    for (auto& a : position) a.resize(n);
  }
  /// v^{n+½} as spans, for the stages that read or write it.
  std::array<std::span<double>, dim> velocity_spans() {
    std::array<std::span<double>, dim> v;
    for (int a = 0; a < dim; ++a) v[a] = velocity[a];
    return v;
  }
  std::array<std::span<const double>, dim> velocity_spans() const {
    std::array<std::span<const double>, dim> v;
    for (int a = 0; a < dim; ++a) v[a] = velocity[a];
    return v;
  }
};

/// What can go wrong in a step, found where it happens and turned into an exception by the loop
/// after the step, and the wall guard's count of corrections.
struct StepHealth {
  StepFailure failure;       ///< a failed constitutive update, and the count of fallbacks
  std::exception_ptr error;  ///< a failed neighbour search or sample
  double energy_budget = std::numeric_limits<double>::infinity();  ///< J/m the kinetic energy may not exceed
  std::string blow_up;  ///< what the close of the last step found insane (blow_up.h); empty: nothing
  std::size_t guard_corrections = 0;  ///< times the wall guard had to act (expected 0)

  bool failed() const { return failure.failed() || error; }
};

/// The histories' sampling: whom a step that samples calls, and when.
template <int dim>
struct SamplingOf {
  /// Called inside the steps that sample (RunControl::on_sample).
  std::function<void(const StepSampleOf<dim>&)> sampler;
  bool due = false;        ///< this step samples; changed only between steps (every thread reads it)
  double last_time = 0.0;  ///< t^n of the last sample
};

/// The cuts of the loops over soil rows that differ in cost per particle (range_balancer.h): loop 1,
/// loop 2 and loop 4 of each material group.
struct LoopBalancers {
  RangeBalancer prepare, momentum;
  std::vector<RangeBalancer> stress;

  /// Sizes them for a parallel region of `threads` over `groups` material groups (serial).
  void use_threads(int threads, std::size_t groups) {
    stress.resize(groups);
    prepare.use_threads(threads);
    momentum.use_threads(threads);
    for (RangeBalancer& b : stress) b.use_threads(threads);
  }
  void rebalance() {
    prepare.rebalance();
    momentum.rebalance();
    for (RangeBalancer& b : stress) b.rebalance();
  }
};

/// Reusable work space of the loop (no allocation after the first step): where the step stands, and
/// one part for each job of the step.
template <int dim>
struct WorkspaceOf {
  double previous_dt = 0.0;  ///< Δt_{n−1}; 0 before the first step, so the first kick is half a step
  double time = 0.0;         ///< t^n (s), for the walls' motion
  double sound_speed = 0.0;  ///< current c (m/s)
  double max_speed = 0.0;    ///< largest soil speed |v^{n+½}| after the last step (m/s)
  std::size_t moving = 0;    ///< soil particles faster than the rest speed after the last step
  PairDataOf<dim> pairs;     ///< searched at a step's start if due; loop 1 fills, loops 2–4 read
  NextStateOf<dim> next;     ///< loops 2 and 4 write it, loop 3 and the close read it
  StepHealth health;         ///< loop 4, the search, the sample and the close report to it
  SamplingOf<dim> sampling;  ///< between loops 2 and 3 of a step that samples
  LoopBalancers balance;     ///< cut loops 1, 2 and 4 between the threads
  MirrorImagesOf<dim> images;  ///< the soil's images behind the symmetry planes, rebuilt with the pairs

  WorkspaceOf(const SolverSetupOf<dim>& setup, const ParticlesOf<dim>& p)
      : sound_speed(setup.sound_speed),
        pairs(p.size()),
        next(p),
        images(setup.symmetry_planes, setup.image_reach) {
    // Cells on a grid fixed for the run (neighbours/cell_list.h), so a row depends on positions
    // alone, as a domain decomposition needs; the plane keeps the bounding box's grid, which its
    // shipped results were made with.
    if constexpr (dim == 3) pairs.neighbours.anchor_cells_at({setup.domain.lo.x, setup.domain.lo.y, setup.domain.lo.z});
  }
};
using Workspace = WorkspaceOf<2>;

/// Rebuilds the soil's mirror images from the soil at `soil` (the positions of the search about
/// to be made, or of the one a checkpoint saved) and sizes the workspace for them (serial).
template <int dim>
void rebuild_images(ParticlesOf<dim>& p, WorkspaceOf<dim>& work, const std::type_identity_t<Coordinates<dim>>& soil) {
  work.images.rebuild(p, soil);
  work.pairs.volume.resize(p.size());
  work.next.resize(p.size());
}

namespace detail {
/// Calls f(model, fallback, begin, end) for every group, with its model's own type.
template <class F>
void for_each_group(const MaterialGroups& groups, F&& f) {
  for (const MaterialGroup& group : groups)
    std::visit(
        [&](const auto& model) {
          using Model = std::decay_t<decltype(model)>;
          f(model, std::get<Model>(group.fallback), group.begin, group.end);
        },
        group.model);
}

/// The largest wave speed of the particles [begin, end) of one material: the P-wave speed of its
/// elasticity at each particle's pressure, or for a UMAT plug-in √(ρc²/ρ) with ρc² from its DDSDDE
/// at each particle's state (UmatModel::wave_modulus) and ρ the material's: the time step follows
/// the stiffest particle.
template <class Model, int dim>
double largest_wave_speed(const Model& model, const ParticlesOf<dim>& p, std::size_t begin, std::size_t end) {
  if constexpr (requires { model.wave_modulus(State{}, UmatCall{}); }) {
    // The material's density, as for the models of constant stiffness: a free-surface particle's SPH
    // density, short of neighbours, would inflate its c.
    const double density = model.params().density;
    double c = 0.0;
    for (std::size_t i = begin; i < end; ++i)
      c = std::max(c, std::sqrt(model.wave_modulus(p.state[i], umat_call_at(p, i, 0.0)) / density));
    return c;
  } else {
    return largest_p_wave_speed(model.elasticity(), p, begin, end);
  }
}

/// The largest P-wave speed of the soil now: each state-dependent material's over its own
/// particles at their state, and the constant-stiffness materials' fixed one.
template <int dim>
double current_sound_speed(const MaterialGroups& groups, const SolverSetupOf<dim>& setup, const ParticlesOf<dim>& p) {
  double c = setup.constant_stiffness_sound_speed;
  for (const MaterialGroup& group : groups)
    if (group.pressure_dependent)
      c = std::max(c,
                   std::visit([&](const auto& m) { return largest_wave_speed(m, p, group.begin, group.end); },
                              group.model));
  return c;
}

/// Whether the first step needs c from the particles: a UMAT's stiffness at the start is its
/// DDSDDE at each particle's geostatic state, which the probe at zero stress does not know.
inline bool stiffness_from_particles(const MaterialGroups& groups) {
  return std::any_of(groups.begin(), groups.end(),
                     [](const MaterialGroup& g) { return std::holds_alternative<UmatModel>(g.model); });
}

/// What the time loop's global decisions read of the soil after a step (rest, blow-up, the next
/// time step), gathered in one pass: the one reduction of a step over the particles, which a
/// domain-decomposed run reduces across its ranks (largest speed and the particle that has it, sum
/// of moving particles and of kinetic energy, the first insane particle; docs/method/mpi-design.md).
struct SoilTotals {
  double v2_max = 0.0;   ///< largest |v|² (m²/s²)
  double kinetic = 0.0;  ///< Σ ½ m |v|² (J; per metre in the plane)
  std::size_t moving = 0;        ///< particles faster than the rest speed
  std::size_t fastest = 0;       ///< the particle of v2_max
  std::size_t first_insane = 0;  ///< the first particle particle_sane() rejects; soil_count: none
};
template <int dim>
SoilTotals soil_totals(const SolverSetupOf<dim>& setup, const ParticlesOf<dim>& p, double sound_speed) {
  const double rest2 = setup.rest.speed * setup.rest.speed, c2 = sound_speed * sound_speed;
  SoilTotals t{.first_insane = p.soil_count};
  for (std::size_t i = 0; i < p.soil_count; ++i) {
    const Vec<dim> v = p.velocity(i);
    const double v2 = dot(v, v);
    if (v2 > t.v2_max) t.v2_max = v2, t.fastest = i;
    t.moving += v2 > rest2;
    t.kinetic += 0.5 * p.mass[i] * v2;
    if (t.first_insane == p.soil_count && !particle_sane(p, i, v2, c2, setup.domain)) t.first_insane = i;
  }
  return t;
}

/// The serial end of a step: swap in v^{n+½} and ρ^{n+1}, the wall guard, the soil's totals
/// (soil_totals: the step's largest speed, moving particles, blow-up checks of blow_up.h), and
/// whether the next step must search neighbours.
template <int dim>
void close_step(const MaterialGroups& groups, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p,
                WorkspaceOf<dim>& work, double dt) {
  const auto velocity = p.velocity_arrays();
  NextStateOf<dim>& next = work.next;
  for (int a = 0; a < dim; ++a) std::swap(*velocity[a], next.velocity[a]);
  std::swap(p.density, next.density);
  // The ghosts' entries of next.position are those the last swap left there: where walls move,
  // bring them up to date first, so that the walls' motion below moves each ghost on from where it
  // is.
  const auto position = p.position_arrays();
  if (setup.walls.any) {
    const auto ghosts = static_cast<std::ptrdiff_t>(p.soil_count);
    for (int a = 0; a < dim; ++a)
      std::copy(position[a]->begin() + ghosts, position[a]->end(), next.position[a].begin() + ghosts);
  }
  for (int a = 0; a < dim; ++a) std::swap(*position[a], next.position[a]);
  setup.walls.advance(p, work.time, dt);
  work.time += dt;
  const GuardPushes pushed = setup.guard.apply(p, work.time);
  work.health.guard_corrections += pushed.count;
  work.images.place(p);  // where the soil is now, the wall guard's corrections included
  work.previous_dt = dt;
  const SoilTotals totals = soil_totals(setup, p, work.sound_speed);
  work.max_speed = std::sqrt(totals.v2_max);
  work.moving = totals.moving;
  StepHealth& health = work.health;
  if (totals.first_insane < p.soil_count) {
    health.blow_up = particle_blow_up(p, totals.first_insane, work.sound_speed, setup.domain);
  } else if (!(totals.kinetic <= health.energy_budget)) {
    const std::string unit = dim == 2 ? " J/m" : " J";
    health.blow_up = "blow-up: the kinetic energy " + std::to_string(totals.kinetic) + unit +
                     " exceeds all the energy the soil held at the start, " +
                     std::to_string(health.energy_budget) + unit + " (potential, elastic, kinetic); " +
                     fastest_particle(p, totals.fastest) + kBlowUpHint;
  } else if (pushed.count > std::max<std::size_t>(10, p.soil_count / 100)) {
    health.blow_up = "blow-up: the wall guard pushed " + std::to_string(pushed.count) +
                     " soil particles back through a wall in one step" +
                     (pushed.past_edge > 0 ? ", " + std::to_string(pushed.past_edge) +
                                                 " of them past its edge" + kLongerFloorHint<dim>
                                           : std::string()) +
                     kBlowUpHint;
  }
  if (!health.blow_up.empty()) return;  // a search on such positions would fail or exhaust memory
  work.pairs.search_next = work.pairs.neighbours.search_needed(p.coordinates());
  if (setup.pressure_dependent_stiffness && work.pairs.search_next)
    work.sound_speed = current_sound_speed(groups, setup, p);
}
}  // namespace detail

/// One leapfrog step of length dt from t^n to t^{n+1} (stages/leapfrog.h), then `on_closed()` on
/// one thread; each group's `fallback` takes over a failed stress update (stages/stress_update.h).
/// Call from every thread of a parallel region, or outside one.
template <int dim, class OnClosed>
void advance_groups(const MaterialGroups& groups, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p,
                    WorkspaceOf<dim>& work, double dt, OnClosed&& on_closed) {
  PairDataOf<dim>& pairs = work.pairs;
  PairList<dim>& nl = pairs.neighbours;
  NextStateOf<dim>& next = work.next;
  StepHealth& health = work.health;
  const auto& m = setup.momentum;
  const double kick_dt = kick_interval(work.previous_dt, dt);
  // body(i) for i in [begin, end): this thread's part by `balance`, timed in its CPU time (wall
  // time would count the time the thread was descheduled on a busy machine); no barrier.
  const int thread = omp_get_thread_num(), threads = omp_get_num_threads();
  const auto balanced = [&](RangeBalancer& balance, std::size_t begin, std::size_t end, auto&& body) {
    if (threads == 1 || balance.threads() != threads) {  // outside a region, or not sized for it
#pragma omp for schedule(static) nowait
      for (auto s = static_cast<std::ptrdiff_t>(begin); s < static_cast<std::ptrdiff_t>(end); ++s)
        body(static_cast<std::size_t>(s));
      return;
    }
    const double start = thread_cpu_seconds();
    const auto [first, last] = balance.part(begin, end, thread);
    for (std::size_t i = first; i < last; ++i) body(i);
    balance.record(thread, thread_cpu_seconds() - start);
  };
  if (pairs.search_next) {
    if (work.images.any()) {
#pragma omp single
      rebuild_images(p, work, p.coordinates());
    }
    try {
      nl.search(p.coordinates(), setup.kernel, p.soil_count, p.id, p.image_begin);  // every thread throws alike, or none
    } catch (...) {
#pragma omp critical(soilsph_search_failure)
      if (!health.error) health.error = std::current_exception();
    }
  }
  // After the search, which may change the number of mirror images.
  const auto all = static_cast<std::ptrdiff_t>(p.size()), soil = static_cast<std::ptrdiff_t>(p.soil_count),
             lattice_end = static_cast<std::ptrdiff_t>(p.image_begin);
  if (!health.error) {
    // 1. Pairs at x^n; ghosts take σ^n, ρ^n from the soil (their v^{n−½} came with the last step);
    //    the artificial stress from σ^n, then what the pairs of the momentum equation read (σ/ρ², v, ρ,
    //    m packed per particle), soil and ghosts. The soil rows and the ghost rows are shared out
    //    apart, so that every thread fills the soil rows it reads again in loops 2 and 4 (a soil
    //    row costs several ghost rows) and no thread waits between the two halves (nowait: the
    //    ghosts read only what the soil rows do not write). The soil's mirror images copy their soil
    //    particles, before the ghosts, whose rows read them.
    const auto prepare_sources = [&](std::size_t i) {
      pairs.volume[i] = particle_volume(p, i);
      if (m.artificial_stress.enabled() && set_artificial_stress(p, i, m.artificial_stress.epsilon()))
        pairs.any_tension.store(true, std::memory_order_relaxed);
      set_momentum_source(p, i);
    };
    setup.kernel.visit([&](const auto& kernel) {  // the shape chosen once, outside the loops
      balanced(work.balance.prepare, 0, p.soil_count, [&](std::size_t i) {
        nl.fill_row(i, p.coordinates(), kernel);
        prepare_sources(i);
      });
      if (lattice_end < all) {
#pragma omp for schedule(static)
        for (std::ptrdiff_t s = lattice_end; s < all; ++s) {
          work.images.copy_stress(p, static_cast<std::size_t>(s));
          prepare_sources(static_cast<std::size_t>(s));
        }
      }
#pragma omp for schedule(static)
      for (std::ptrdiff_t s = soil; s < lattice_end; ++s) {
        const auto b = static_cast<std::size_t>(s);
        nl.fill_row(b, p.coordinates(), kernel);
        mirror_stress_onto_ghost(p, nl, b, setup.ghost_body_force);
        prepare_sources(b);
      }
    });
    // 2. a^n (eq 12, 36–38) and the kick to v^{n+½}, kept apart from v^{n−½}, which neighbours read.
    //    Each particle's own ρ and σ, whatever its material: no interface model (docs/reference/scenes.md).
    const bool any_tension = pairs.any_tension.load(std::memory_order_relaxed);  // after loop 1's barrier
    const auto acceleration = acceleration_arrays(p);
    const auto velocity = p.velocity_arrays();
    balanced(work.balance.momentum, 0, p.soil_count, [&](std::size_t i) {
      const AccelerationOf<dim> a = acceleration_of(p, nl, m, i, any_tension);
      for (int k = 0; k < dim; ++k) {
        (*acceleration[k])[i] = a[k];
        next.velocity[k][i] = (*velocity[k])[i] + kick_dt * a[k];
      }
    });
#pragma omp barrier
    if (work.sampling.due) {
#pragma omp single
      try {
        work.sampling.last_time = work.time;
        work.sampling.sampler({work.time, p, nl, m, std::as_const(next).velocity_spans()});
      } catch (...) {
        health.error = std::current_exception();
      }
    }
    // 3. Ghosts take v^{n+½}: the soil's images first, which the ghosts' rows read.
    if (lattice_end < all) {
#pragma omp for schedule(static)
      for (std::ptrdiff_t s = lattice_end; s < all; ++s)
        work.images.copy_velocity(p, static_cast<std::size_t>(s), next.velocity_spans());
    }
#pragma omp for schedule(static)
    for (std::ptrdiff_t s = soil; s < lattice_end; ++s)
      mirror_velocity_onto_ghost(p, nl, static_cast<std::size_t>(s), next.velocity_spans());
    // 4. Eq 23 and eq 11 in one pass from v^{n+½} at x^n; σ^{n+1}; ρ^{n+1}; drift to x^{n+1} (no
    //    stage of this loop reads σ of a neighbour; the pairs take x_i − x_j from the positions, so
    //    x^{n+1} goes to next.position). One loop per material, its model chosen once here by every
    //    thread alike. The groups are disjoint: one barrier after the last.
    const auto x = p.coordinates();
    std::size_t group = 0;
    detail::for_each_group(groups, [&](const auto& model, const auto& fallback, std::size_t begin,
                                       std::size_t end) {
      balanced(work.balance.stress[group++], begin, end, [&](std::size_t i) {
        const KinematicRatesOf<dim> rates = kinematic_rates_of(p, nl, i, std::as_const(next).velocity_spans(),
                                                               pairs.volume, setup.kinematics);
        update_particle_stress(model, fallback, p, i, rates.L, dt, health.failure);
        next.density[i] = p.density[i] + dt * rates.density_rate;
        for (int a = 0; a < dim; ++a) next.position[a][i] = x[a][i] + dt * next.velocity[a][i];
      });
    });
#pragma omp barrier
  }
#pragma omp single
  {
    if (!health.failed()) detail::close_step(groups, setup, p, work, dt);
    pairs.any_tension.store(false, std::memory_order_relaxed);  // loop 2 has read it
    work.balance.rebalance();
    on_closed();
  }
}

/// One group over the whole soil with one model (tests).
template <class Model, int dim>
MaterialGroups single_material(const Model& model, const ParticlesOf<dim>& p) {
  bool pressure_dependent = false;
  if constexpr (requires { model.elasticity(); }) pressure_dependent = stiffness_follows_state(model);
  return {MaterialGroup{Material(model), Material(fallback_model(model)), 0, p.soil_count, pressure_dependent}};
}

/// One step of the whole soil with one model and its own fallback, without a callback (tests).
template <class Model, int dim>
void advance(const Model& model, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p, WorkspaceOf<dim>& work,
             double dt) {
  const MaterialGroups groups = single_material(model, p);
  work.balance.use_threads(1, groups.size());
  advance_groups(groups, setup, p, work, dt, [] {});
}

/// Why a run returned.
enum class StopReason {
  EndTime,  ///< it reached the scene's end time
  Rest,     ///< the soil came to rest (rest.h)
  Request,  ///< the caller asked it to stop (RunControl::stop_requested, e.g. on a signal)
};

struct RunStatistics {
  std::size_t steps = 0;
  double end_time = 0.0;  ///< time reached (s)
  double wall_seconds = 0.0;
  std::size_t guard_corrections = 0;
  StopReason stop = StopReason::EndTime;
  bool stopped_at_rest = false;
  double smallest_time_step = 0.0, largest_time_step = 0.0;  ///< s
  std::size_t workspace_bytes = 0;          ///< neighbour list and step buffers
  std::size_t fallback_stress_updates = 0;  ///< updates whose first attempt failed (stages/stress_update.h)
};

/// Chooses each step's length: the CFL step from the current state, shortened only to land exactly
/// on the end time (never below half a CFL step before it). Frames are written at the first step
/// that reaches within half a step of each frame time, not by shortening steps onto it, so that
/// the output settings cannot change the solution.
class StepClock {
 public:
  /// The clock of a run of `setup` (either dimension's SolverSetupOf).
  template <class Setup>
  explicit StepClock(const Setup& setup)
      : cfl_(setup.cfl), h_(setup.kernel.smoothing_length()), end_time_(setup.end_time),
        frame_interval_(setup.frame_interval), next_frame_(setup.frame_interval) {}
  /// A clock at time t whose next frame is due at next_frame (a resumed run).
  template <class Setup>
  StepClock(const Setup& setup, double t, double next_frame) : StepClock(setup) {
    t_ = t, next_frame_ = next_frame;
  }

  double time() const { return t_; }
  double next_frame() const { return next_frame_; }
  /// The step of the last next_step() is shorter than the CFL step (it approaches the end time).
  bool shortened() const { return dt_ < cfl_dt_; }
  /// The length of the next step for the current sound speed and largest speed.
  double next_step(double sound_speed, double max_speed) {
    cfl_dt_ = cfl_time_step(cfl_, h_, sound_speed, max_speed);
    const double remaining = end_time_ - t_;
    lands_ = cfl_dt_ >= remaining * (1.0 - 1e-12);
    dt_ = lands_ ? remaining : (cfl_dt_ > 0.5 * remaining ? 0.5 * remaining : cfl_dt_);
    return dt_;
  }
  /// The CFL step of the last next_step(), before any shortening.
  double cfl_step() const { return cfl_dt_; }
  /// Advances the time by the step taken; true if a frame is due at the new time.
  bool step_taken() {
    t_ = lands_ ? end_time_ : t_ + dt_;  // the end exactly, without accumulated round-off
    if (t_ < next_frame_ - 0.5 * dt_ && !lands_) return false;
    // The first multiple of the interval beyond this step (not repeated additions, which stop
    // advancing when the interval is below the round-off of the time).
    const double interval = frame_interval_;
    next_frame_ = std::max(next_frame_, interval * (std::floor((t_ + 0.5 * dt_) / interval) + 1.0));
    return true;
  }
  bool at_end() const { return t_ >= end_time_; }

 private:
  double cfl_, h_, end_time_, frame_interval_;
  double t_ = 0.0, dt_ = 0.0, cfl_dt_ = 0.0, next_frame_;
  bool lands_ = false;
};

/// What the time loop carries from one step to the next besides the particles: with them, all a
/// run needs to continue bit for bit (a checkpoint saves both; output/checkpoint.h).
struct LoopState {
  RunStatistics stats;  ///< so far: steps, time reached, wall time, counts, Δt range
  double next_frame = 0.0;   ///< s, time of the next frame
  double previous_dt = 0.0;  ///< Δt_{n−1} (s)
  double sound_speed = 0.0;  ///< current c (m/s)
  double max_speed = 0.0;    ///< largest soil speed after the last step (m/s)
  std::size_t moving = 0;    ///< soil particles faster than the rest speed after the last step
  RestWatch::Memory rest;
  std::vector<double> search_x, search_y, search_z;  ///< every particle's position at the last neighbour search (z: space only)
};

/// The positions of the neighbour search a LoopState saved.
template <int dim>
Coordinates<dim> searched_positions(const LoopState& state) {
  if constexpr (dim == 2)
    return {state.search_x, state.search_y};
  else
    return {state.search_x, state.search_y, state.search_z};
}

/// What a caller can do to a run besides watching its frames and steps.
template <int dim>
struct RunControlOf {
  /// Polled after every step (serial): true stops the run there, as at its end (a signal).
  std::function<bool()> stop_requested;
  /// Called with the state to continue from: every checkpoint_interval of simulated time, when the
  /// run stops at rest or on request, and before the steps that are shortened to land on the end
  /// time (so that a run continued from it to a later end time steps exactly as one that never
  /// stopped). Serial; the particles hold the state of the LoopState's time.
  std::function<void(const ParticlesOf<dim>&, const LoopState&)> checkpoint;
  /// Continue from this state (the particles must hold the state saved with it): no frame at its
  /// time, which the run that saved it wrote if one was due.
  const LoopState* resume = nullptr;
  /// Called (serially, inside the step) at the first step that starts at or after `first_sample` and
  /// then at the first step starting at or after each later multiple of `sample_interval` (s).
  std::function<void(const StepSampleOf<dim>&)> on_sample;
  double sample_interval = 0.0;
  double first_sample = 0.0;
  /// Called once (serially) when a step fails, before the error is rethrown, with the statistics
  /// up to the last step that closed: what a summary of the failed run reports.
  std::function<void(const RunStatistics&)> on_failure;
};
using RunControl = RunControlOf<2>;

namespace detail {
/// The time loop of run_groups, one named step per job: its state between steps (the clock, the
/// rest watch, the statistics, the next checkpoint and sample) and what happens before the first
/// step, after each step (serially, on one thread) and at the end.
template <int dim, class OnFrame, class OnStep>
class TimeLoop {
 public:
  TimeLoop(const MaterialGroups& groups, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p,
           OnFrame& on_frame, OnStep& on_step, const RunControlOf<dim>& control)
      : groups_(groups),
        setup_(setup),
        p_(p),
        on_frame_(on_frame),
        on_step_(on_step),
        control_(control),
        resume_(control.resume),
        work_(setup, p),
        clock_(resume_ ? StepClock(setup, resume_->stats.end_time, resume_->next_frame) : StepClock(setup)),
        rest_(resume_ ? RestWatch(setup.rest, resume_->rest) : RestWatch(setup.rest)),
        stats_(resume_ ? resume_->stats : RunStatistics{}) {
    if (resume_)
      continue_from(*resume_);
    else if (stiffness_from_particles(groups))
      work_.sound_speed = current_sound_speed(groups, setup, p);
    work_.health.energy_budget = starting_energy();
    wall_before_ = stats_.wall_seconds;
    next_checkpoint_ =
        setup.checkpoint_interval > 0.0
            ? setup.checkpoint_interval * (std::floor(clock_.time() / setup.checkpoint_interval) + 1)
            : std::numeric_limits<double>::infinity();
    next_sample_ = control.first_sample;
    work_.sampling.sampler = control.on_sample;
  }

  /// The run: the first frame and step, then chunks of steps until a step decides to stop.
  RunStatistics run(ThreadTuner& tuner) {
    start();
    while (!stop_) run_chunk(tuner);
    if (error_) {
      if (control_.on_failure) control_.on_failure(statistics_now());
      std::rethrow_exception(error_);
    }
    stats_ = statistics_now();
    stats_.workspace_bytes =
        work_.pairs.neighbours.bytes() +
        (2 * dim + 2) * p_.size() * sizeof(double);  // the next state (v, ρ, x), volume
    return stats_;
  }

 private:
  using Clock = std::chrono::steady_clock;

  /// The workspace as the run that saved `state` left it, and the same neighbour candidates: the
  /// search from the same positions.
  void continue_from(const LoopState& state) {
    work_.previous_dt = state.previous_dt;
    work_.sound_speed = state.sound_speed;
    work_.max_speed = state.max_speed;
    work_.moving = state.moving;
    work_.health.guard_corrections = stats_.guard_corrections;
    work_.time = state.stats.end_time;
    setup_.walls.set_velocities(p_, work_.time);
    work_.health.failure.restore_fallback_updates(stats_.fallback_stress_updates);
    // The images of the search the checkpoint saved, from the soil's positions there, placed where
    // the soil is now: what the run that saved it held.
    const std::size_t saved = state.search_x.size();
    if (work_.images.any()) rebuild_images(p_, work_, searched_positions<dim>(state));
    if (p_.size() != saved || (!work_.images.any() && p_.image_count() != 0))
      throw std::runtime_error("the checkpoint holds " + std::to_string(saved) + " particles, the scene's soil, ghosts and mirror images " +
                               std::to_string(p_.size()) + ": it was not written by this scene");
    work_.pairs.neighbours.search(searched_positions<dim>(state), setup_.kernel, p_.soil_count, p_.id, p_.image_begin);
    work_.pairs.search_next = work_.pairs.neighbours.search_needed(p_.coordinates());
  }

  /// All the energy the soil holds now (blow_up.h): the kinetic energy may never exceed it.
  double starting_energy() const {
    double energy = 0.0;
    for_each_group(groups_, [&](const auto& model, const auto&, std::size_t begin, std::size_t end) {
      energy +=
          energy_budget(p_, model.elasticity(), setup_.momentum.gravity, setup_.potential_datum, begin, end);
    });
    return energy;
  }

  /// Before the first step: the frame at t = 0 (not when resuming) and the first step's length.
  void start() {
    if (!resume_) on_frame_(p_, 0.0);
    plan_step();
    if (!resume_) stats_.smallest_time_step = stats_.largest_time_step = clock_.cfl_step();
    prepare_step();
  }

  /// Chunks of about kChunkSeconds of wall time, each one parallel region with the tuner's count.
  void run_chunk(ThreadTuner& tuner) {
    constexpr double kChunkSeconds = 0.05;
    const auto chunk_start = Clock::now();
    const std::size_t first = stats_.steps,
                      steps_now = tuner.trying() ? std::max<std::size_t>(chunk_ / 4, 4) : chunk_;
    work_.balance.use_threads(tuner.threads(), groups_.size());
    const auto after_step = [this] { close(); };
#pragma omp parallel num_threads(tuner.threads())
    for (std::size_t k = 0; k < steps_now && !stop_; ++k)  // `stop_` is read after the closing barrier
      advance_groups(groups_, setup_, p_, work_, dt_, after_step);
    const std::chrono::duration<double> seconds = Clock::now() - chunk_start;
    const auto steps = static_cast<double>(stats_.steps - first);
    tuner.record(seconds.count(), steps * static_cast<double>(p_.soil_count));
    if (steps > 0.0 && seconds.count() > 0.0)
      chunk_ =
          std::clamp<std::size_t>(static_cast<std::size_t>(kChunkSeconds * steps / seconds.count()), 4, 4096);
  }

  /// After each step, serially: a failure stops the run and is rethrown after the region.
  void close() {
    try {
      throw_if_failed();
      const bool frame_due = clock_.step_taken();
      ++stats_.steps;
      on_step_(clock_.time(), stats_.steps);
      decide_stop();
      if (frame_due || stop_) on_frame_(p_, clock_.time());
      if (stop_) {
        if (stats_.stop != StopReason::EndTime || !checkpoint_before_end_) checkpoint();
        return;
      }
      checkpoint_if_due();
      plan_step();
      prepare_step();
    } catch (...) {
      error_ = std::current_exception();
      stop_ = true;
    }
  }

  /// The step's failure, blow-up or failed search as an exception naming the step and its time.
  void throw_if_failed() const {
    const StepHealth& health = work_.health;
    if (!health.failed() && health.blow_up.empty()) return;
    const std::string when =
        " (step " + std::to_string(stats_.steps + 1) + ", t = " + std::to_string(clock_.time()) + " s)";
    if (!health.blow_up.empty()) throw BlowUp(health.blow_up + when);
    if (health.failure.failed()) throw IntegrationError(health.failure.message() + when);
    try {
      std::rethrow_exception(health.error);
    } catch (const std::exception& e) {
      throw std::runtime_error(e.what() + when);
    }
  }

  /// Rest, the end time or the caller's request stop the run.
  void decide_stop() {
    stats_.stopped_at_rest = rest_.at_rest(clock_.time(), work_.moving, p_.soil_count);
    const bool requested = control_.stop_requested && control_.stop_requested();
    stats_.stop = stats_.stopped_at_rest ? StopReason::Rest
                  : clock_.at_end()      ? StopReason::EndTime
                                         : StopReason::Request;
    stop_ = stats_.stopped_at_rest || clock_.at_end() || requested;
  }

  /// The checkpoint of every checkpoint_interval of simulated time.
  void checkpoint_if_due() {
    if (clock_.time() < next_checkpoint_) return;
    checkpoint();
    while (next_checkpoint_ <= clock_.time()) next_checkpoint_ += setup_.checkpoint_interval;
  }

  /// The next step's length, and the range of the CFL steps.
  void plan_step() {
    dt_ = clock_.next_step(work_.sound_speed, work_.max_speed);
    stats_.smallest_time_step = std::min(stats_.smallest_time_step, clock_.cfl_step());
    stats_.largest_time_step = std::max(stats_.largest_time_step, clock_.cfl_step());
  }

  /// Serial, once dt is known: the checkpoint before the end's short steps, and whether the step samples.
  void prepare_step() {
    if (clock_.shortened() && !checkpoint_before_end_) {
      checkpoint_before_end_ = true;
      checkpoint();
    }
    schedule_sample();
  }

  void schedule_sample() {
    SamplingOf<dim>& sampling = work_.sampling;
    if (!sampling.sampler) return;
    if (sampling.due)
      next_sample_ =
          control_.sample_interval * (std::floor(sampling.last_time / control_.sample_interval) + 1.0);
    sampling.due = clock_.time() >= next_sample_;
  }

  /// The statistics so far, with the counts the workspace kept during the loop.
  RunStatistics statistics_now() const {
    RunStatistics now = stats_;
    now.end_time = clock_.time();
    now.wall_seconds = wall_before_ + std::chrono::duration<double>(Clock::now() - start_).count();
    now.guard_corrections = work_.health.guard_corrections;
    now.fallback_stress_updates = work_.health.failure.fallback_updates();
    return now;
  }

  void checkpoint() {
    if (!control_.checkpoint) return;
    LoopState state{
        .stats = statistics_now(),
        .next_frame = clock_.next_frame(),
        .previous_dt = work_.previous_dt,
        .sound_speed = work_.sound_speed,
        .max_speed = work_.max_speed,
        .moving = work_.moving,
        .rest = rest_.memory(),
        .search_x = work_.pairs.neighbours.search_x(),
        .search_y = work_.pairs.neighbours.search_y(),
        .search_z = {},
    };
    if constexpr (dim == 3) state.search_z = work_.pairs.neighbours.search_positions(2);
    control_.checkpoint(p_, state);
  }

  const MaterialGroups& groups_;
  const SolverSetupOf<dim>& setup_;
  ParticlesOf<dim>& p_;
  OnFrame& on_frame_;
  OnStep& on_step_;
  const RunControlOf<dim>& control_;
  const LoopState* resume_;
  const Clock::time_point start_ = Clock::now();
  WorkspaceOf<dim> work_;
  StepClock clock_;
  RestWatch rest_;
  RunStatistics stats_;
  double wall_before_ = 0.0;                          ///< wall time of the run before it resumed here (s)
  double next_checkpoint_ = 0.0, next_sample_ = 0.0;  ///< s
  bool checkpoint_before_end_ = false;  ///< written before the steps shortened onto the end time
  double dt_ = 0.0;                     ///< the length of the next step
  bool stop_ = false;
  std::exception_ptr error_;
  std::size_t chunk_ = 16;  ///< steps in the next parallel region
};
}  // namespace detail

/// Runs to the end time, or until the soil is at rest if the scene asks for it, or until `control`
/// asks it to stop. Calls on_frame(particles, t) at t = 0 (not when resuming), every frame interval
/// and at the end (the time reached), and on_step(t, steps) after every step. A failed update or
/// search is rethrown after the region: IntegrationError naming the particle, BlowUp (blow_up.h),
/// or the search's std::runtime_error, each with the step and time added. `tuner` picks the threads
/// of each chunk of steps (sph/thread_tuner.h); by default the OpenMP maximum throughout.
template <int dim, class OnFrame, class OnStep>
RunStatistics run_groups(const MaterialGroups& groups, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p,
                         OnFrame&& on_frame, OnStep&& on_step,
                         ThreadTuner tuner = ThreadTuner(omp_get_max_threads(), false),
                         const RunControlOf<dim>& control = {}) {
  using Loop = detail::TimeLoop<dim, std::remove_reference_t<OnFrame>, std::remove_reference_t<OnStep>>;
  return Loop(groups, setup, p, on_frame, on_step, control).run(tuner);
}

/// The same with one model for the whole soil (tests).
template <class Model, int dim, class OnFrame, class OnStep>
RunStatistics run(const Model& model, const SolverSetupOf<dim>& setup, ParticlesOf<dim>& p, OnFrame&& on_frame,
                  OnStep&& on_step, ThreadTuner tuner = ThreadTuner(omp_get_max_threads(), false),
                  const RunControlOf<dim>& control = {}) {
  return run_groups(single_material(model, p), setup, p, std::forward<OnFrame>(on_frame),
                    std::forward<OnStep>(on_step), tuner, control);
}

}  // namespace soilsph::sph
