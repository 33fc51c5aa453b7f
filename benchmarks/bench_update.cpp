// Cost of one material-point update, per model × integrator, for an elastic and a plastic step.
// Every iteration applies the same increment to the same state, so the plastic cases stay plastic.
// Increments of 1e-4 (the upper middle of what an SPH step produces, 1e-6 to 1e-3); the plastic step
// also at 1e-6 and 1e-3 (labels plastic-1e-6, plastic-1e-3). For MCC also `dust`: a free-surface
// particle of the SPH collapse, p_c = 0.025 Pa on the wet side (p = 0.6 p_c), under one step's shear
// and extension, a trial ~1e4 times the surface's size outside it (z = 6GΔλ > 1e3).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "constitutive/stress_test.h"

using namespace soilsph;

namespace {
struct Case {
  State start;
  Mat3 increment;
};

Mat3 triaxial(double axial) {
  return Vec3(-axial, 0.3 * axial, 0.3 * axial).asDiagonal();
}

/// An elastic and a plastic starting point for each model (the plastic one on the surface).
template <class Model>
std::pair<Case, Case> cases(const Model& model) {
  State s;
  if constexpr (Model::kHasPreconsolidation) {
    s.stress = isotropic_stress(100e3);
    s.pc = model.initial_preconsolidation(s.stress, 1.0);  // NC: triaxial compression is plastic at once
    return {{s, 1e-4 * Mat3::Identity()}, {s, triaxial(1e-4)}};
  } else {
    s.stress = isotropic_stress(20e3);
    // Sheared until it yields: one shear reaches the D-P cone; Mohr–Coulomb, wider in triaxial
    // compression, needs more (its first increments stay elastic).
    State on_surface = model.update(s, triaxial(5e-2), Mat3::Zero());
    for (int k = 0; k < 20 && !(on_surface.plastic_multiplier > 0.0); ++k)
      on_surface = model.update(on_surface, triaxial(5e-2), Mat3::Zero());
    return {{s, -1e-5 * Mat3::Identity()}, {on_surface, triaxial(1e-4)}};
  }
}

/// A dust particle (see the file's comment), as in tests/constitutive/test_integrators.cpp.
template <class Model>
Case dust(const Model& model) {
  const double pc = 0.025, p = 0.6 * pc, M = model.M();
  State s;
  s.stress = isotropic_stress(p);
  s.stress(0, 1) = s.stress(1, 0) = std::sqrt(M * M * p * (pc - p)) / std::sqrt(3.0);  // q on the surface
  s.pc = pc;
  Mat3 d_eps = Vec3(1e-4, -0.8e-4, 0.0).asDiagonal();
  d_eps(0, 1) = d_eps(1, 0) = 0.6e-4;
  return {s, d_eps};
}

template <class Model>
void register_model(const std::string& name, const Model& base) {
  for (Integrator scheme : kIntegrators) {
    auto params = base.params();
    params.integrator = scheme;
    const Model model(params);
    const auto [elastic, plastic] = cases(model);
    // The plastic step also at the ends of the SPH range of strain increments, 1e-6 and 1e-3.
    const Case plastic_small{plastic.start, 1e-2 * plastic.increment};
    const Case plastic_large{plastic.start, 10.0 * plastic.increment};
    std::vector<std::pair<std::string, Case>> kinds = {
        {"elastic", elastic}, {"plastic", plastic}, {"plastic-1e-6", plastic_small}, {"plastic-1e-3", plastic_large}};
    if constexpr (Model::kHasPreconsolidation) kinds.emplace_back("dust", dust(model));
    for (const auto& [kind, c] : kinds) {
      const std::string label = name + "/" + std::string(integrator_name(scheme)) + "/" + kind;
      benchmark::RegisterBenchmark(label.c_str(), [model, c = c](benchmark::State& st) {
        State start = c.start;
        Mat3 increment = c.increment;
        for (auto _ : st) {
          benchmark::DoNotOptimize(start);
          benchmark::DoNotOptimize(increment);
          State next = model.update(start, increment, Mat3::Zero());
          benchmark::DoNotOptimize(next);
        }
        const State probe = model.update(c.start, c.increment, Mat3::Zero());
        st.counters["plastic"] = probe.plastic_multiplier > 0.0 ? 1.0 : 0.0;
      });
    }
  }
}
}  // namespace

int main(int argc, char** argv) {
  for (const auto& [name, label, material] : stress_test_materials()) {
    std::visit(
        [&](const auto& model) {
          if constexpr (PlasticModel<std::decay_t<decltype(model)>>) register_model(label, model);
        },
        material);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
