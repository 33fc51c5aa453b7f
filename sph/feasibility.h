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
/// Bytes per particle (soil or ghost): measured 2645 B with 48 neighbour slots (docs/method/sph.md).
inline constexpr double kBytesPerParticle = 2700;
/// The same in space, soil and ghosts together: measure_run (`soilsph check`) gave 2.87–2.93 KB on
/// the shipped axisymmetric column (quarter at r0/Δp = 10 and 20, whole at 20) and the slab
/// (2026-12-05).
inline constexpr double kBytesPerParticle3 = 2900;

/// Most frames a run may write: each frame rewrites the indexes of all before it
/// (sph/output/frame_writer.h), so their cost grows with the square of the count.
inline constexpr double kMaxFrames = 1e4;

RunEstimate estimate_run(const Scene& scene);
/// The same for a scene of space, from its shape's volume and its walls' areas in cells.
RunEstimate estimate_run(const Scene3& scene);

/// The same measured on a scene's particles as built (a 3D scene's, whose counts depend on how its
/// shapes fill the lattice): the counts; the memory as the particles' arrays (ParticlesOf::bytes()),
/// the neighbour list after one search of them (bytes_per_particle()) and the solver's step buffers
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
