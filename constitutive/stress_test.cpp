#include "constitutive/stress_test.h"

#include "constitutive/tangent.h"

#include <chrono>
#include <cmath>
#include <random>
#include <sstream>

namespace soilsph {

namespace {
enum class Segment { Any, Extension, Compression, Shear, Reverse };

/// A unit-norm symmetric direction with the character of the segment.
Mat3 direction(std::mt19937_64& rng, Segment kind) {
  std::normal_distribution<double> n(0.0, 1.0);
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) a(i, j) = a(j, i) = n(rng);
  if (kind == Segment::Shear) a = deviator(a);
  const double volume = std::abs(n(rng)) + 0.5;  // a clear volumetric part of the chosen sign
  if (kind == Segment::Extension) a = deviator(a) + volume * Mat3::Identity();
  if (kind == Segment::Compression) a = deviator(a) - volume * Mat3::Identity();
  return a / a.norm();
}

Mat3 skew(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  Mat3 w = Mat3::Zero();
  w(0, 1) = u(rng), w(0, 2) = u(rng), w(1, 2) = u(rng);
  return w - w.transpose();
}

/// Every fourth fresh state of a model with p_c is "dust": p from 1e-9 to 1 Pa, the free-surface
/// particles of an SPH collapse, whose surface is tiny against one increment's trial (where an MCC
/// return once accepted a non-root, docs/method/integrators.md); the others are 1–200 kPa.
template <class Model>
State fresh_state(const Model&, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  State s;
  const bool dust = Model::kHasPreconsolidation && u(rng) < 0.25;
  const double p = dust ? 1e-9 * std::pow(1e9, u(rng)) : 1e3 * std::pow(200.0, u(rng));
  s.stress = isotropic_stress(p);
  if constexpr (Model::kHasPreconsolidation) s.pc = p * std::pow(20.0, u(rng));  // OCR 1–20
  return s;
}

template <class Model>
bool out_of_range(const Model&, const State& s) {
  if (std::abs(mean_pressure(s.stress)) > 1e9) return true;
  if constexpr (Model::kHasPreconsolidation) return s.pc < 1e-9 || s.pc > 1e9;
  return false;
}

/// A UMAT plug-in's checks: finite STRESS and STATEV (the adapter throws for a non-finite one), the
/// declared ranges of STATEV, and now and then DDSDDE against central differences of the update.
std::string check_umat(const UmatModel& model, const State& start, const Mat3& d_eps, const State& s, long k,
                       const StressTestOptions& options, StressTestResult& r) {
  for (const StateVariableRange& range : options.state_ranges) {
    const double v = s.umat.statev[static_cast<std::size_t>(range.index - 1)];
    if (!(v >= range.lo && v <= range.hi)) {
      std::ostringstream out;
      out << "STATEV(" << range.index << ") = " << v << " left its range [" << range.lo << ", " << range.hi
          << "]";
      return out.str();
    }
  }
  if (options.tangent_every <= 0 || k % options.tangent_every != 0) return "";
  const Mat6 returned = model.returned_tangent(start, d_eps);
  const Mat6 differences = finite_difference_tangent(model, start, d_eps);
  const double error = (returned - differences).norm() / std::max(differences.norm(), 1e-300);
  ++r.tangent_checks;
  r.worst_tangent_error = std::max(r.worst_tangent_error, error);
  if (error <= options.tangent_tolerance) return "";
  ++r.tangent_mismatches;
  std::ostringstream out;
  out << "DDSDDE differs from central differences of the update by " << error
      << " (relative, Frobenius norm)";
  return out.str();
}

/// Checks one updated state; returns a description of what is wrong, or "" when all is well.
template <class Model>
std::string check(const Model& model, const State& start, const Mat3& d_eps, const State& s,
                  const StressTestOptions& options, StressTestResult& r) {
  if (!s.stress.allFinite() || !std::isfinite(s.pc) || !std::isfinite(s.plastic_multiplier))
    return "non-finite state";
  double f = model.normalized_yield(s.stress, s.pc);
  const double scale = increment_scale(model, start, d_eps);
  if constexpr (Model::kHasPreconsolidation) {
    // f = M² p (p − p_c) + q² is computed from a trial of the increment's scale: where that is far
    // larger than the surface (dust), f carries the round-off of scale², not of (M p_c)².
    const double surface = model.M() * s.pc;
    if (scale > surface) f *= (surface / scale) * (surface / scale);
  }
  r.max_yield = std::max(r.max_yield, f);
  if (!(f <= options.yield_tolerance))
    return "outside the yield surface (normalized f = " + std::to_string(f) + ")";
  if (!(s.plastic_multiplier >= 0.0)) return "negative plastic multiplier";
  if constexpr (Model::kHasPreconsolidation) {
    if (!(s.pc > 0.0)) return "p_c <= 0";
    // On the surface q² = M² p (p_c − p) needs p ≥ 0, to the round-off of the increment's stress
    // scale (which the result cannot inflate: relative to the result's p_c a runaway p_c of 1e143 Pa
    // at p = −1e7 Pa would pass).
    const double p = mean_pressure(s.stress);
    r.min_pressure_ratio = std::min(r.min_pressure_ratio, p / s.pc);
    if (!(p >= -options.yield_tolerance * scale)) {
      std::ostringstream out;
      out << "negative p' (p' = " << p << " Pa, p_c = " << s.pc << " Pa, the increment's scale " << scale
          << " Pa)";
      return out.str();
    }
  }
  return "";
}

/// The checks of the model's kind: a UMAT plug-in's, or a built-in model's.
template <class Model>
std::string check_update(const Model& model, const State& start, const Mat3& d_eps, const State& s, long k,
                         const StressTestOptions& options, StressTestResult& r) {
  if constexpr (std::is_same_v<Model, UmatModel>) {
    if (!s.stress.allFinite()) return "non-finite state";
    return check_umat(model, start, d_eps, s, k, options, r);
  } else {
    return check(model, start, d_eps, s, options, r);
  }
}

void classify(const StateMarks& marks, StressTestResult& r) {
  r.at_apex += marks.at_apex;
  r.near_zero_pressure += marks.near_zero_pressure;
  r.near_critical_state += marks.near_critical_state;
}

void record(StressTestResult& r, long k, const std::string& what, const State& s, const Mat3& d_eps,
            const Mat3& d_spin) {
  r.first_problem = "increment " + std::to_string(k) + ": " + what;
  r.problem_start = s;
  r.problem_strain = d_eps;
  r.problem_spin = d_spin;
}

template <class Model>
StressTestResult walk(const Model& model, const StressTestOptions& options) {
  StressTestResult r;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> segment_length(1, 50), segment_kind(0, 4);
  const double log_min = std::log(1e-6), log_max = std::log(options.max_increment);
  const auto t0 = std::chrono::steady_clock::now();

  State state = fresh_state(model, rng);
  Mat3 previous = direction(rng, Segment::Any), current = previous;
  Segment kind = Segment::Any;
  int left = 0;
  for (long k = 0; k < options.increments; ++k) {
    if (k > 0 && k % options.restart_every == 0) state = fresh_state(model, rng);
    if (left == 0) {
      left = segment_length(rng);
      kind = static_cast<Segment>(segment_kind(rng));
      previous = current;
      current = kind == Segment::Reverse ? Mat3(-previous) : direction(rng, kind);
    }
    --left;
    const double size = std::exp(log_min + (log_max - log_min) * u(rng));
    const Mat3 d_eps = size * current;
    const Mat3 d_spin = skew(rng, size);
    ++r.increments;
    if (d_eps.trace() > 0.0) ++r.extension;
    if (kind == Segment::Reverse) ++r.unloading;
    try {
      const State next = model.update(state, d_eps, d_spin);
      const std::string problem = check_update(model, state, d_eps, next, k, options, r);
      if (!problem.empty()) {
        if (r.violations++ == 0 && r.first_problem.empty()) record(r, k, problem, state, d_eps, d_spin);
        state = fresh_state(model, rng);
        continue;
      }
      if (next.plastic_multiplier > 0.0) ++r.plastic;
      if constexpr (requires { model.marks(next); }) classify(model.marks(next), r);
      state = out_of_range(model, next) ? fresh_state(model, rng) : next;
    } catch (const IntegrationError& e) {
      if (r.failures++ == 0 && r.first_problem.empty()) record(r, k, e.what(), state, d_eps, d_spin);
      state = fresh_state(model, rng);
    } catch (const UmatError& e) {  // a plug-in's non-finite result, PNEWDT to the end, or crash
      if (r.failures++ == 0 && r.first_problem.empty()) record(r, k, e.what(), state, d_eps, d_spin);
      state = fresh_state(model, rng);
    }
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}
}  // namespace

StressTestResult run_stress_test(const Material& material, Integrator integrator,
                                 const StressTestOptions& options) {
  return std::visit(
      [&](const auto& model) -> StressTestResult {
        using Model = std::decay_t<decltype(model)>;
        if constexpr (!PlasticModel<Model>) {
          throw std::invalid_argument("stress test: a " + std::string(Model::kName) +
                                      " material has no integrator of soilsph's to test");
        } else {
          auto params = model.params();
          params.integrator = integrator;
          return walk(Model(params), options);
        }
      },
      material);
}

StressTestResult run_umat_stress_test(const UmatModel& umat, const StressTestOptions& options) {
  for (const StateVariableRange& range : options.state_ranges)
    if (range.index < 1 || range.index > umat.params().state_variables)
      throw std::invalid_argument("stress test: STATEV(" + std::to_string(range.index) +
                                  ") is not a state variable of the UMAT (state_variables = " +
                                  std::to_string(umat.params().state_variables) + ")");
  return walk(umat, options);
}

std::vector<StressTestMaterial> stress_test_materials() {
  DruckerPrager::Params dp{};  // Table 1
  dp.density = 2000.0, dp.young_modulus = 1.0e6, dp.poisson_ratio = 0.3, dp.friction_angle = 35.0;
  dp.cohesion = 0.0, dp.dilatancy_angle = 0.0;
  DruckerPrager::Params dp_cohesive = dp;
  dp_cohesive.cohesion = 5e3, dp_cohesive.dilatancy_angle = 10.0;
  ModifiedCamClay::Params mcc{};  // Table 1
  mcc.density = 2000.0, mcc.poisson_ratio = 0.3, mcc.friction_angle = 35.0, mcc.compression_index = 0.085;
  mcc.swelling_index = 0.019, mcc.initial_void_ratio = 0.68,
  mcc.elasticity = Elasticity::Kind::PressureDependent;
  mcc.young_modulus = 1.0e6, mcc.elastic_pressure_floor = 1.0e3;
  ModifiedCamClay::Params mcc_constant = mcc;
  mcc_constant.elasticity = Elasticity::Kind::Constant;
  ModifiedCamClay::Params mcc_bounded = mcc_constant;  // softening stops at 100 Pa, above the walk's dust states
  mcc_bounded.minimum_preconsolidation = 100.0;
  MohrCoulomb::Params mc{};  // the Table 1 soil's E, ν, φ
  mc.density = 2000.0, mc.young_modulus = 1.0e6, mc.poisson_ratio = 0.3, mc.friction_angle = 35.0;
  mc.cohesion = 5e3, mc.dilatancy_angle = 10.0;
  MohrCoulomb::Params mc_cutoff = mc;
  mc_cutoff.tension_cutoff = 2e3;
  return {{"drucker-prager (Table 1, c = 0, psi = 0)", "dp", DruckerPrager(dp)},
          {"drucker-prager (c = 5 kPa, psi = 10 deg)", "dp-cohesive", DruckerPrager(dp_cohesive)},
          {"modified-cam-clay (Table 1, pressure-dependent K)", "mcc", ModifiedCamClay(mcc)},
          {"modified-cam-clay (Table 1, constant E)", "mcc-constant-E", ModifiedCamClay(mcc_constant)},
          {"modified-cam-clay (Table 1, constant E, p_c,min = 100 Pa)", "mcc-bounded", ModifiedCamClay(mcc_bounded)},
          {"mohr-coulomb (c = 5 kPa, psi = 10 deg)", "mc", MohrCoulomb(mc)},
          {"mohr-coulomb (c = 5 kPa, psi = 10 deg, T = 2 kPa)", "mc-cutoff", MohrCoulomb(mc_cutoff)}};
}

}  // namespace soilsph
