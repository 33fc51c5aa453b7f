#pragma once
/// @file
/// What a scene will cost, estimated and checked before anything is allocated or stepped: a run
/// that cannot fit in memory, would take longer than the scene allows, or has no meaningful time
/// step is refused with the numbers, instead of ending in std::bad_alloc, 2.5e13 silent steps or a
/// "complete" run of zero steps.
#include <cstddef>
#include <string>

#include "sph/scene.h"
#include "sph/scene_3d.h"
#include "sph/solver.h"

namespace soilsph::sph {

struct RunEstimate {
  std::size_t soil_particles = 0, boundary_particles = 0;
  double memory_bytes = 0;  ///< particles, states, neighbour list, step buffers
  double sound_speed = 0;   ///< m/s, the P-wave speed c at the start
  double time_step = 0;     ///< s, the CFL step at rest: the largest the run takes while c holds
  double steps = 0;         ///< to the end time at that step: the fewest it can take
  double seconds = 0;       ///< steps × (soil + boundary particles) at kAssumedThroughput
};

/// Particle-steps per second assumed by the estimate: the slowest measured one-thread rate
/// (MCC with `implicit`, 0.6e6; D-P runs 1.3–2.2e6; docs/performance.md), rounded down.
inline constexpr double kAssumedThroughput = 5e5;
/// Bytes a particle holds in a run, per dimension (index 2 or 3): its arrays (ParticlesOf::bytes()
/// of one particle: 552 B a soil and 213 B a ghost particle in the plane, 704 and 349 B in space),
/// the step's buffers (48 B; 64 B in space), its row's place (44 B; 52 B) and its row of the
/// neighbour list (neighbours/neighbour_list.h) at h = 1.3Δp, slots of 24 B: a soil particle's 24
/// lattice candidates in the plane, 92 in space; a ghost's at most the mean of its layers' below a
/// lattice soil, 5 and 15.7 (a ghost out of the soil's reach holds none). Rounded up.
inline constexpr double kSoilBytes[4] = {0, 0, 1300, 3100};
inline constexpr double kGhostBytes[4] = {0, 0, 450, 850};

/// Most frames a run may write: each frame rewrites the indexes of all before it
/// (sph/output/frame_writer.h), so their cost grows with the square of the count.
inline constexpr double kMaxFrames = 1e4;

RunEstimate estimate_run(const Scene& scene);
/// The same for a scene of space, from its shape's volume and its walls' areas in cells.
RunEstimate estimate_run(const Scene3& scene);

/// The same measured on a scene's particles as built (a 3D scene's, whose counts depend on how its
/// shapes fill the lattice): the counts; the memory as the particles' arrays (ParticlesOf::bytes()),
/// the neighbour list after one search of them (PairList::bytes()) and the solver's step buffers
/// (RunStatistics::workspace_bytes); the step at rest and the steps and run time as estimate_run's.
template <int dim>
RunEstimate measure_run(const SolverSetupOf<dim>& setup, const ParticlesOf<dim>& particles);

/// Throws ParameterError, naming the scene, the numbers and the key that changes them, if the time
/// step is not finite and positive, the soil is too soft to carry its own weight (P-wave speed below
/// the free-fall speed √(2gH): the weakly compressible scheme needs |v| ≪ c), the memory exceeds
/// `memory_available` bytes, the estimated run time exceeds [scene] max_run_hours, or the frames
/// would be more than kMaxFrames.
template <class SceneT>
void check_feasible(const SceneT& scene, const RunEstimate& estimate, double memory_available);

/// Physical memory of this machine (bytes).
double physical_memory();

/// "2.5 min", "3.1 h", "4.2e+03 days": a duration for messages.
std::string human_duration(double seconds);

}  // namespace soilsph::sph
