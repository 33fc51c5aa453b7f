#include "verification/reference/cvode_reference.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "verification/driver/mixed_control_algebra.h"

namespace soilsph::verification {

namespace {

/// The ODE state: stress (Voigt, 6), total strain (Voigt, engineering shears, 6), p_c, pore pressure
/// and, for a model with a dilatancy cut-off only (so that every other model's ODE is unchanged), the
/// plastic dilation.
constexpr int kSize = 14;
constexpr int kStrain = 6;
constexpr int kPc = 12;
constexpr int kPorePressure = 13;
constexpr int kDilation = 14;
template <class Model>
int ode_size(const Model& model) {
  return limits_dilation(model) ? kSize + 1 : kSize;
}
/// The plastic dilation of the ODE state y (0 where it has no such component).
template <class Model>
double dilation_of(const Model& model, const double* y) {
  return limits_dilation(model) ? y[kDilation] : 0.0;
}
/// Output intervals (in increments) shorter than this are bridged without CVODE.
constexpr double kTooClose = 1e-9;

template <class Model>
constexpr bool kPlastic = PlasticModel<Model>;

/// The rates at one state for one leg and branch (elastic or plastic).
struct Rates {
  Vec6 stress = Vec6::Zero();
  Vec6 strain = Vec6::Zero();
  double pc = 0.0;
  double pore_pressure = 0.0;       ///< u̇, 0 on a drained leg
  double dilation = 0.0;            ///< λ̇ tr n_g, the plastic dilation's rate
  double plastic_multiplier = 0.0;  ///< λ̇, 0 on the elastic branch
  bool defined = true;              ///< false where n_f:D:n_g + H ≤ 0: no plastic solution
};

/// The rates at (σ, p_c) with plastic dilation d: the model that flows there (ψ = 0 past a dilatancy
/// cut-off) gives them.
template <class Model>
Rates rates(const Model& given, const Leg& leg, const Partition& part, const Vec6& stress, double pc, double d,
            bool plastic) {
  const Model& model = flowing_model(given, d);
  const Mat3 sigma = stress_from_voigt(stress);
  const Moduli D = model.elasticity().at(mean_pressure(sigma));
  Mat6 C = voigt_stiffness(D);
  Vec6 b = Vec6::Zero();
  double denominator = 1.0;
  Mat3 n_g = Mat3::Zero();
  if constexpr (kPlastic<Model>) {
    if (plastic) {
      n_g = model.flow_direction(sigma, pc);
      const Mat3 n_f = model.yield_gradient(sigma, pc);
      const Vec6 a = stress_to_voigt(D.stiffness(n_g));  // D : n_g
      b = stress_to_voigt(D.stiffness(n_f));             // n_f : D, paired with engineering strain rates
      denominator = ddot(n_f, D.stiffness(n_g)) + model.hardening_modulus(sigma, pc);
      if (!(denominator > 0.0)) {
        Rates undefined;
        undefined.defined = false;
        return undefined;
      }
      C -= a * b.transpose() / denominator;
    }
  }
  Rates r;
  r.strain = leg.increment;  // imposed strain rates per unit pseudo-time (one increment)
  r.pore_pressure = solve_free(C, part, leg.increment, r.strain);
  r.stress = C * r.strain;
  if constexpr (kPlastic<Model>) {
    if (plastic) {
      r.plastic_multiplier = b.dot(r.strain) / denominator;
      r.pc = model.hardening_rate(sigma, pc, r.plastic_multiplier, n_g);  // MCC: eq 27 in rate form
      r.dilation = r.plastic_multiplier * n_g.trace();
    }
  }
  return r;
}

/// What the CVODE callbacks need; `plastic` is the branch being integrated.
template <class Model>
struct Problem {
  const Model* model;
  const Leg* leg;
  Partition part;
  bool plastic = false;
  std::string last_error;
};

Vec6 stress_of(const double* y) {
  return Eigen::Map<const Vec6>(y);
}

template <class Model>
int right_hand_side(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  auto& problem = *static_cast<Problem<Model>*>(data);
  const double* v = N_VGetArrayPointer(y);
  const Rates r = rates(*problem.model, *problem.leg, problem.part, stress_of(v), v[kPc],
                        dilation_of(*problem.model, v), problem.plastic);
  if (!r.defined) {
    problem.last_error =
        "the plastic modulus n_f:D:n_g + H is not positive, so plastic loading has no continuum solution "
        "from this state (the Drucker-Prager apex with psi = 0, or Cam-Clay softening on the dry side that "
        "outweighs the elastic stiffness)";
    return -1;  // unrecoverable
  }
  double* d = N_VGetArrayPointer(ydot);
  Eigen::Map<Vec6>{d} = r.stress;
  Eigen::Map<Vec6>{d + kStrain} = r.strain;
  d[kPc] = r.pc;
  d[kPorePressure] = r.pore_pressure;
  if (limits_dilation(*problem.model)) d[kDilation] = r.dilation;
  return r.stress.allFinite() && std::isfinite(r.pc) ? 0 : 1;  // 1: recoverable, CVODE cuts the step
}

/// The plastic dilation at which the model stops dilating (+∞: none).
template <class Model>
double cutoff_of(const Model& model) {
  if constexpr (requires { model.dilatancy_cutoff(); })
    return model.dilatancy_cutoff();
  else
    return std::numeric_limits<double>::infinity();
}

/// The smallest p_c the model's softening reaches (MCC's minimum_preconsolidation), 0 for none.
template <class Model>
double softening_bound(const Model& model) {
  if constexpr (requires { model.minimum_preconsolidation(); })
    return model.minimum_preconsolidation();
  else
    return 0.0;
}

/// g[0], elastic branch: the yield function (its crossing of 0 upwards is first yield); plastic
/// branch: λ̇ (its crossing of 0 downwards is elastic unloading). g[1]: p_c − p_c,min, whose crossing
/// downwards is where softening stops (the rate ṗ_c jumps from θ p_c,min ε̇_v^p to 0 there, a kink no
/// step may straddle); constant where the model has no bound. g[2]: cut-off − plastic dilation, whose
/// crossing downwards is where dilation stops (ψ jumps to 0); constant without a cut-off.
template <class Model>
int switching_function(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
  auto& problem = *static_cast<Problem<Model>*>(data);
  const double* v = N_VGetArrayPointer(y);
  if constexpr (kPlastic<Model>) {
    if (problem.plastic) {
      g[0] = rates(*problem.model, *problem.leg, problem.part, stress_of(v), v[kPc], dilation_of(*problem.model, v),
                   true)
                 .plastic_multiplier;
    } else {
      g[0] = problem.model->normalized_yield(stress_from_voigt(stress_of(v)), v[kPc]);
    }
  } else {
    g[0] = -1.0;
  }
  const double bound = softening_bound(*problem.model);
  g[1] = bound > 0.0 ? v[kPc] - bound : 1.0;
  g[2] = limits_dilation(*problem.model) ? cutoff_of(*problem.model) - v[kDilation] : 1.0;
  return 0;
}

template <class Model>
void record_error(int code, const char* module, const char* function, char* message, void* data) {
  if (code >= 0) return;  // warnings
  std::string& last = static_cast<Problem<Model>*>(data)->last_error;
  last = std::string(module) + " " + function + ": " + message + (last.empty() ? "" : " (" + last + ")");
}

/// Owns the SUNDIALS objects of one run.
struct Solver {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector tolerances = nullptr;
  N_Vector rates = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  void* memory = nullptr;
  ~Solver() {
    if (memory) CVodeFree(&memory);
    if (linear_solver) SUNLinSolFree(linear_solver);
    if (matrix) SUNMatDestroy(matrix);
    if (tolerances) N_VDestroy(tolerances);
    if (rates) N_VDestroy(rates);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }
};

template <class Model>
void check(int flag, const char* what, const Problem<Model>& problem) {
  if (flag >= 0) return;
  char* name = CVodeGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  std::string message = std::string("cvode reference: ") + what + " failed (" + name + ")";
  std::free(name);
  if (!problem.last_error.empty()) message += ": " + problem.last_error;
  throw std::runtime_error(message);
}

/// The branch at the start of a leg. Off the surface: elastic. On it: plastic when an elastic step
/// of the leg's loading leaves the surface, i.e. f(σ + δ σ̇_el) > f(σ) for a short δ (a thousandth
/// of an increment). That is λ̇ > 0 to first order; for neutral loading (λ̇ = 0, e.g. an undrained
/// path from the tip of the MCC ellipse) the convexity of f decides, and the state must flow.
template <class Model>
bool starts_plastic(const Model& model, const Leg& leg, const Partition& part, const Vec6& stress, double pc,
                    double surface_tolerance) {
  if constexpr (kPlastic<Model>) {
    const Mat3 sigma = stress_from_voigt(stress);
    if (model.normalized_yield(sigma, pc) < -surface_tolerance) return false;
    constexpr double kProbe = 1e-3;
    // Elastic rates: the same for the model and its ψ = 0 twin, so the dilation does not matter.
    const Vec6 trial = stress + kProbe * rates(model, leg, part, stress, pc, 0.0, false).stress;
    return model.yield(stress_from_voigt(trial), pc) > model.yield(sigma, pc);
  }
  return false;
}

template <class Model>
PointHistory integrate_legs(const Model& model, const State& initial, std::span<const Leg> legs,
                            const CvodeOptions& options) {
  PointHistory history{{Mat3::Zero(), initial}};
  if (legs.empty()) return history;
  Problem<Model> problem{&model, &legs[0], Partition(legs[0]), false, {}};
  Solver s;
  if (SUNContext_Create(nullptr, &s.context) != 0) throw std::runtime_error("cvode reference: no SUNContext");
  const int size = ode_size(model);
  s.y = N_VNew_Serial(size, s.context);
  s.tolerances = N_VNew_Serial(size, s.context);
  s.rates = N_VNew_Serial(size, s.context);
  double* y = N_VGetArrayPointer(s.y);
  Eigen::Map<Vec6>{y} = stress_to_voigt(initial.stress);
  Eigen::Map<Vec6>{y + kStrain}.setZero();
  y[kPc] = initial.pc;
  y[kPorePressure] = 0.0;
  if (limits_dilation(model)) y[kDilation] = initial.plastic_dilation;
  // Absolute tolerances scaled to the stress level of the test.
  const double stress_scale = std::max({initial.stress.cwiseAbs().maxCoeff(), initial.pc, 1.0});
  double* atol = N_VGetArrayPointer(s.tolerances);
  for (int k = 0; k < size; ++k)
    atol[k] = options.absolute_tolerance * ((k < kStrain || k >= kPc) && k != kDilation ? stress_scale : 1.0);

  s.memory = CVodeCreate(CV_BDF, s.context);
  if (!s.memory) throw std::runtime_error("cvode reference: CVodeCreate failed");
  check(CVodeSetErrHandlerFn(s.memory, record_error<Model>, &problem), "CVodeSetErrHandlerFn", problem);
  check(CVodeInit(s.memory, right_hand_side<Model>, 0.0, s.y), "CVodeInit", problem);
  check(CVodeSetUserData(s.memory, &problem), "CVodeSetUserData", problem);
  check(CVodeSVtolerances(s.memory, options.relative_tolerance, s.tolerances), "CVodeSVtolerances", problem);
  s.matrix = SUNDenseMatrix(size, size, s.context);
  s.linear_solver = SUNLinSol_Dense(s.y, s.matrix, s.context);
  check(CVodeSetLinearSolver(s.memory, s.linear_solver, s.matrix), "CVodeSetLinearSolver", problem);
  check(CVodeSetMaxNumSteps(s.memory, options.max_steps_per_increment), "CVodeSetMaxNumSteps", problem);
  check(CVodeRootInit(s.memory, 3, switching_function<Model>), "CVodeRootInit", problem);
  check(CVodeSetNoInactiveRootWarn(s.memory), "CVodeSetNoInactiveRootWarn", problem);

  std::size_t leg_index = 0;
  int increment = 0;  // of the current leg, from 0: where a failure is reported
  try {
    for (const Leg& given : legs) {
      const Leg leg = resolve_leg(given, history.back());
      increment = 0;
      problem.leg = &leg;
      problem.part = Partition(leg);
      if (!leg.undrained) y[kPorePressure] = 0.0;  // drainage open: the excess has dissipated
      problem.plastic =
          starts_plastic(model, leg, problem.part, stress_of(y), y[kPc], options.surface_tolerance);
      check(CVodeReInit(s.memory, 0.0, s.y), "CVodeReInit", problem);
      int directions[3] = {problem.plastic ? -1 : 1, -1, -1};
      check(CVodeSetRootDirection(s.memory, directions), "CVodeSetRootDirection", problem);
      sunrealtype t = 0.0;
      for (int k = 1; k <= leg.increments; ++k) {
        for (int switches = 0;; ++switches) {
          if (k - t <= kTooClose) {
            // A root a hair before the output time (e.g. reloading to the previous turning point,
            // which falls on an increment): CVODE cannot start on such an interval, and one Euler
            // step over it is exact to (k − t)² ≤ 1e-18 of an increment.
            if (right_hand_side<Model>(t, s.y, s.rates, &problem) != 0)
              throw std::runtime_error("cvode reference: " + problem.last_error);
            N_VLinearSum(1.0, s.y, k - t, s.rates, s.y);
            t = k;
            check(CVodeReInit(s.memory, t, s.y), "CVodeReInit", problem);
            break;
          }
          problem.last_error.clear();
          const int flag = CVode(s.memory, k, s.y, &t, CV_NORMAL);
          check(flag, "CVode", problem);
          if (flag != CV_ROOT_RETURN) break;
          if (switches > 100)
            throw std::runtime_error("cvode reference: more than 100 branch switches in one increment");
          int found[3] = {0, 0, 0};
          check(CVodeGetRootInfo(s.memory, found), "CVodeGetRootInfo", problem);
          if (found[1] != 0) {
            // Softening reached the bound: p_c onto it exactly, where the model's rate is 0, and on.
            y[kPc] = softening_bound(model);
          } else if (found[2] != 0) {
            // Dilation reached the cut-off: onto it exactly, where the ψ = 0 twin flows on.
            y[kDilation] = cutoff_of(model);
          } else {
            // Switch branch at the root and restart there, so no step straddles the kink: to
            // elastic where λ̇ reached 0; to plastic where f reached 0 unless the loading is
            // tangential and turns inwards (then the state stays elastic).
            problem.plastic = !problem.plastic && starts_plastic(model, leg, problem.part, stress_of(y), y[kPc],
                                                                 std::numeric_limits<double>::infinity());
          }
          directions[0] = problem.plastic ? -1 : 1;
          check(CVodeReInit(s.memory, t, s.y), "CVodeReInit", problem);
          check(CVodeSetRootDirection(s.memory, directions), "CVodeSetRootDirection", problem);
        }
        PointSample sample;
        sample.strain = strain_from_voigt(Eigen::Map<const Vec6>(y + kStrain));
        sample.state.stress = stress_from_voigt(stress_of(y));
        sample.state.pc = y[kPc];
        sample.state.plastic_dilation = dilation_of(model, y);
        sample.pore_pressure = y[kPorePressure];
        history.push_back(sample);
        increment = k;
      }
      ++leg_index;
    }
  } catch (const std::runtime_error& e) {
    throw IncrementError(e.what(), leg_index, increment);
  }
  return history;
}

}  // namespace

PointHistory cvode_reference(const Material& material, const State& initial, std::span<const Leg> legs,
                             const CvodeOptions& options) {
  return std::visit([&](const auto& model) { return integrate_legs(model, initial, legs, options); },
                    material);
}

}  // namespace soilsph::verification
