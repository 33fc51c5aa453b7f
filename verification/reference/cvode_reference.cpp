#include "verification/reference/cvode_reference.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "verification/driver/mixed_control_algebra.h"
#include "verification/reference/yield_surfaces.h"

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

/// The rates at one state for one leg and set of active surfaces (none: the elastic branch).
struct Rates {
  Vec6 stress = Vec6::Zero();
  Vec6 strain = Vec6::Zero();
  double pc = 0.0;
  double pore_pressure = 0.0;                      ///< u̇, 0 on a drained leg
  double dilation = 0.0;                           ///< Σ λ̇_k tr n_g,k, the plastic dilation's rate
  std::array<double, kMaxSurfaces> multipliers{};  ///< λ̇_k of the active surfaces, 0 elsewhere
  Mat3 plastic_strain = Mat3::Zero();              ///< ε̇^p = Σ λ̇_k n_g,k
  bool defined = true;  ///< false where the plastic system is singular or n_f:D:n_g + H ≤ 0
};

bool is_active(unsigned active, int k) {
  return (active >> k) & 1u;
}

/// The branch that holds the stress at the apex of a pyramid (Mohr–Coulomb's, or the tension
/// cut-off's corner σ = T I): σ̇ = 0 and every strain rate plastic. At a hydrostatic stress the
/// principal directions, and with them the planes' gradients, are undefined, so Koiter's rule
/// cannot choose among the planes there (CVODE stalled on them); where the model's own return of a
/// step of the leg's loading stays at the apex (held_apex), the apex is the whole answer: the
/// stress is fixed by the corner, the plastic flow takes the imposed strain rate. Its bit lies
/// above every surface's.
constexpr unsigned kApexBranch = 1u << 31;

/// The rates at (σ, p_c) with plastic dilation d and the surfaces of the bit set `active` flowing
/// (yield_surfaces.h): the model that flows there (ψ = 0 past a dilatancy cut-off) gives them.
template <class Model>
Rates rates(const Model& given, const Leg& leg, const Partition& part, const Vec6& stress, double pc,
            double d, unsigned active) {
  const Model& model = flowing_model(given, d);
  const Mat3 sigma = stress_from_voigt(stress);
  const Moduli D = model.elasticity().at(mean_pressure(sigma));
  Mat6 C = voigt_stiffness(D);
  Rates r;
  r.strain = leg.increment;     // imposed strain rates per unit pseudo-time (one increment)
  if (active == kApexBranch) {  // a strain-controlled leg only (held_apex): σ̇ = 0, ε̇^p = ε̇
    r.plastic_strain = strain_from_voigt(r.strain);
    r.dilation = r.plastic_strain.trace();
    return r;
  }
  if constexpr (kPlastic<Model>) {
    if (active != 0) {
      using Columns = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxSurfaces>;
      using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSurfaces, kMaxSurfaces>;
      const Surfaces surface = surfaces(model, sigma, pc);
      int index[kMaxSurfaces];
      int n = 0;
      for (int k = 0; k < surface_count(model); ++k)
        if (is_active(active, k)) index[n++] = k;
      Columns A(6, n);      // D : n_g,k
      Columns B(6, n);      // n_f,j : D, paired with engineering strain rates
      Square system(n, n);  // n_f,j : D : n_g,k + H_j δ_jk
      for (int a = 0; a < n; ++a) {
        A.col(a) = stress_to_voigt(D.stiffness(surface[index[a]].flow));
        B.col(a) = stress_to_voigt(D.stiffness(surface[index[a]].gradient));
        for (int b = 0; b < n; ++b)
          system(a, b) = ddot(surface[index[a]].gradient, D.stiffness(surface[index[b]].flow));
        system(a, a) += surface[index[a]].hardening;
      }
      if (n == 1) {  // one surface: the rank-one update D − (D:n_g) ⊗ (n_f:D) / (n_f:D:n_g + H)
        if (!(system(0, 0) > 0.0)) {
          r.defined = false;
          return r;
        }
        C -= A.col(0) * B.col(0).transpose() / system(0, 0);
      } else {
        Eigen::FullPivLU<Square> lu(system);
        lu.setThreshold(kSingularPivot);
        if (!lu.isInvertible()) {  // dependent gradients: a smaller set gives the same flow
          r.defined = false;
          return r;
        }
        system = lu.inverse();
        C -= A * system * B.transpose();
      }
      r.pore_pressure = solve_free(C, part, leg.increment, r.strain);
      r.stress = C * r.strain;
      const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSurfaces> loading = B.transpose() * r.strain;
      for (int a = 0; a < n; ++a) {  // λ̇ = G⁻¹ (n_f,j : D : ε̇)
        const double multiplier = n == 1 ? B.col(0).dot(r.strain) / system(0, 0) : system.row(a).dot(loading);
        r.multipliers[index[a]] = multiplier;
        r.pc +=
            model.hardening_rate(sigma, pc, multiplier, surface[index[a]].flow);  // MCC: eq 27 in rate form
        r.dilation += multiplier * surface[index[a]].flow.trace();
        r.plastic_strain += multiplier * surface[index[a]].flow;
      }
      return r;
    }
  }
  r.pore_pressure = solve_free(C, part, leg.increment, r.strain);
  r.stress = C * r.strain;
  return r;
}

/// Koiter's rule at a state: the bit set of the surfaces that flow under the leg's loading. Among
/// the surfaces the stress lies on (normalized value ≥ −tolerance), except those in `leaving`, a
/// set qualifies when its multipliers are all ≥ 0 and under its rates every other such surface has
/// ḟ ≤ 0 (both to a relative 1e-10). The elastic set qualifies first. Several may qualify under
/// mixed control: at the triaxial edge σ1 = σ2 one plane alone keeps σ_yy = σ_zz as well as both
/// do (the other's loading is neutral), but it flows along whichever eigenvector the decomposition
/// calls e1, so the rates would jump as round-off swaps e1 and e2. The set taken is then the one
/// of least plastic strain rate ‖ε̇^p‖ (the symmetric split, as solve_free takes the least-norm
/// strain), the smaller set on a tie.
/// The apex stress, if the stress lies at an apex (hydrostatic and on the yield surface, to 1e-6
/// of the stress scale: CVODE locates the corner to its tolerances) that the leg's loading keeps it
/// at: the leg imposes every strain, and the model's own return of a short step of it (a thousandth
/// of an increment) from there ends at a hydrostatic stress as close.
template <class Model>
std::optional<Mat3> held_apex(const Model& model, const Leg& leg, const Partition& part, const Mat3& sigma,
                              double pc, double d, double tolerance) {
  if constexpr (!HasPlanes<Model>) {
    return std::nullopt;
  } else {
    constexpr double kProbe = 1e-3, kNear = 1e-6;
    if (part.n_free != 0 || model.normalized_yield(sigma, pc) < -tolerance) return std::nullopt;
    const Mat3 step = kProbe * strain_from_voigt(leg.increment);
    const double trial_change =
        model.elasticity().at(mean_pressure(sigma)).stiffness(step).cwiseAbs().maxCoeff();
    const double near = kNear * std::max({sigma.cwiseAbs().maxCoeff(), trial_change, 1.0});
    if (deviator(sigma).cwiseAbs().maxCoeff() > near) return std::nullopt;
    State start;
    start.stress = sigma;
    start.pc = pc;
    start.plastic_dilation = d;
    const Mat3 apex = model.update(start, step, Mat3::Zero()).stress;
    if (deviator(apex).cwiseAbs().maxCoeff() > 1e-3 * near || (apex - sigma).cwiseAbs().maxCoeff() > near)
      return std::nullopt;
    return apex;
  }
}

template <class Model>
unsigned koiter_set(const Model& model, const Leg& leg, const Partition& part, const Vec6& stress, double pc,
                    double d, double tolerance, unsigned leaving) {
  constexpr double kTie = 1e-10;
  const Mat3 sigma = stress_from_voigt(stress);
  if (held_apex(model, leg, part, sigma, pc, d, tolerance)) return kApexBranch;
  const Surfaces surface = surfaces(flowing_model(model, d), sigma, pc);
  unsigned on = 0;
  for (int k = 0; k < surface_count(model); ++k)
    if (surface[k].value >= -tolerance && !is_active(leaving, k)) on |= 1u << k;
  const Rates elastic = rates(model, leg, part, stress, pc, d, 0);
  const double stress_rate_scale = elastic.stress.norm();
  unsigned best = 0;
  double least = std::numeric_limits<double>::infinity();
  for (int size = 0; size <= std::popcount(on); ++size)
    for (unsigned set = 0; set <= on; ++set) {
      if ((set & ~on) != 0 || std::popcount(set) != size) continue;
      const Rates r = set == 0 ? elastic : rates(model, leg, part, stress, pc, d, set);
      if (!r.defined) continue;
      const Mat3 stress_rate = stress_from_voigt(r.stress);
      bool consistent = true;
      for (int k = 0; k < surface_count(model) && consistent; ++k) {
        if (is_active(set, k))
          consistent = r.multipliers[k] >= -kTie * r.strain.norm();
        else if (is_active(on, k))
          consistent =
              ddot(surface[k].gradient, stress_rate) <= kTie * surface[k].gradient.norm() * stress_rate_scale;
      }
      if (!consistent) continue;
      if (set == 0) return 0;
      const double norm = r.plastic_strain.norm();
      if (norm < least * (1.0 - kTie)) best = set, least = norm;
    }
  if (least == std::numeric_limits<double>::infinity())
    throw std::runtime_error(
        "cvode reference: no set of the yield planes the stress lies on meets Koiter's conditions "
        "(multipliers >= 0, no other plane loaded)");
  return best;
}

/// What the CVODE callbacks need; `active` is the branch being integrated: the bit set of the
/// flowing surfaces (0: elastic).
template <class Model>
struct Problem {
  const Model* model;
  const Leg* leg;
  Partition part;
  unsigned active = 0;
  std::string last_error;
  double initial_volumetric_strain = 0.0;  ///< tr ε of the initial state, to which the ODE's strain adds
};

/// The model at the ODE state y: for one whose hardening follows the current specific volume (MCC
/// with hardening_volume = "current", ModifiedCamClay::hardening_at), the model at y's total
/// volumetric strain; the model itself otherwise.
template <class Model>
Model model_at(const Problem<Model>& problem, const double* y) {
  if constexpr (requires { problem.model->hardening_at(0.0); })
    return problem.model->hardening_at(problem.initial_volumetric_strain + y[kStrain] + y[kStrain + 1] +
                                       y[kStrain + 2]);
  else
    return *problem.model;
}

Vec6 stress_of(const double* y) {
  return Eigen::Map<const Vec6>(y);
}

template <class Model>
int right_hand_side(sunrealtype, N_Vector y, N_Vector ydot, void* data) {
  auto& problem = *static_cast<Problem<Model>*>(data);
  const double* v = N_VGetArrayPointer(y);
  const Rates r = rates(model_at(problem, v), *problem.leg, problem.part, stress_of(v), v[kPc],
                        dilation_of(*problem.model, v), problem.active);
  if (!r.defined) {
    problem.last_error = std::popcount(problem.active) > 1
                             ? "the flowing yield planes' system n_f:D:n_g is singular at this state"
                             : "the plastic modulus n_f:D:n_g + H is not positive, so plastic loading has no "
                               "continuum solution from this state (the Drucker-Prager apex with psi = 0, or "
                               "Cam-Clay softening on the dry side that outweighs the elastic stiffness)";
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

/// The switching functions, n = surface_count() of them for the surfaces and two more. g[k], k < n:
/// for a surface that flows, λ̇_k (its crossing of 0 downwards is elastic unloading from it); for
/// one that does not, its yield function (its crossing of 0 upwards is first yield on it). g[n]:
/// p_c − p_c,min, whose crossing downwards is where softening stops (the rate ṗ_c jumps from
/// θ p_c,min ε̇_v^p to 0 there, a kink no step may straddle); constant where the model has no bound.
/// g[n + 1]: cut-off − plastic dilation, whose crossing downwards is where dilation stops (ψ jumps to
/// 0); constant without a cut-off.
template <class Model>
int switching_function(sunrealtype, N_Vector y, sunrealtype* g, void* data) {
  auto& problem = *static_cast<Problem<Model>*>(data);
  const double* v = N_VGetArrayPointer(y);
  const Model model = model_at(problem, v);
  const int n = surface_count(model);
  const unsigned all = (1u << n) - 1u;
  const double d = dilation_of(model, v);
  if (problem.active == kApexBranch) {  // held for the rest of the leg: no surface switches
    for (int k = 0; k < n; ++k) g[k] = 1.0;
  } else if (problem.active != 0) {
    const Rates r = rates(model, *problem.leg, problem.part, stress_of(v), v[kPc], d, problem.active);
    for (int k = 0; k < n; ++k)
      if (is_active(problem.active, k)) g[k] = r.multipliers[k];
  }
  if (problem.active != all && problem.active != kApexBranch) {
    const auto values = surface_values(flowing_model(model, d), stress_from_voigt(stress_of(v)), v[kPc]);
    for (int k = 0; k < n; ++k)
      if (!is_active(problem.active, k)) g[k] = values[k];
  }
  const double bound = softening_bound(model);
  g[n] = bound > 0.0 ? v[kPc] - bound : 1.0;
  g[n + 1] = limits_dilation(model) ? cutoff_of(model) - v[kDilation] : 1.0;
  return 0;
}

/// The root directions of the switching functions for the branch `active`.
void set_directions(std::span<int> directions, unsigned active, int n) {
  for (int k = 0; k < n; ++k) directions[k] = is_active(active, k) ? -1 : 1;
  directions[n] = directions[n + 1] = -1;
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
    const Vec6 trial = stress + kProbe * rates(model, leg, part, stress, pc, 0.0, 0).stress;
    return model.yield(stress_from_voigt(trial), pc) > model.yield(sigma, pc);
  }
  return false;
}

/// The flowing surfaces at the start of a leg: for one surface, starts_plastic; for planes, Koiter's
/// rule among those the stress lies on.
template <class Model>
unsigned active_at_start(const Model& model, const Leg& leg, const Partition& part, const Vec6& stress,
                         double pc, double d, double surface_tolerance) {
  if constexpr (HasPlanes<Model>)
    return koiter_set(model, leg, part, stress, pc, d, surface_tolerance, 0);
  else
    return starts_plastic(model, leg, part, stress, pc, surface_tolerance) ? 1u : 0u;
}

/// The flowing surfaces after a root of the surfaces' switching functions (`found`: CVODE's root
/// information), so that no step straddles the kink. One surface: to elastic where λ̇ reached 0; to
/// plastic where f reached 0 unless the loading is tangential and turns inwards (then the state
/// stays elastic). Planes: Koiter's rule among the planes the stress lies on, without those whose
/// λ̇ reached 0.
template <class Model>
unsigned active_at_root(const Model& model, const Leg& leg, const Partition& part, const Vec6& stress,
                        double pc, double d, double surface_tolerance, unsigned active,
                        std::span<const int> found) {
  if constexpr (HasPlanes<Model>) {
    unsigned leaving = 0;
    for (int k = 0; k < surface_count(model); ++k)
      if (found[k] != 0 && is_active(active, k)) leaving |= 1u << k;
    return koiter_set(model, leg, part, stress, pc, d, surface_tolerance, leaving);
  } else {
    return active == 0 &&
                   starts_plastic(model, leg, part, stress, pc, std::numeric_limits<double>::infinity())
               ? 1u
               : 0u;
  }
}

/// The root directions and CVODE's root information for the n surfaces and the two bounds.
struct Roots {
  std::array<int, kMaxSurfaces + 2> directions{}, found{};
  int n = 0;  ///< surfaces
  std::span<int> directions_used() { return {directions.data(), static_cast<std::size_t>(n + 2)}; }
  std::span<const int> found_used() const { return {found.data(), static_cast<std::size_t>(n + 2)}; }
};

/// Creates the CVODE objects of a run in `s` for `problem`, from `initial`: BDF with a dense
/// linear solver, absolute tolerances scaled to the stress level of the test, and the switching
/// functions (`roots.n` surfaces and two bounds).
template <class Model>
void open_solver(Solver& s, Problem<Model>& problem, const State& initial, const CvodeOptions& options,
                 const Roots& roots) {
  const Model& model = *problem.model;
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
  // The absolute tolerances' stress scale: the initial stresses, or from a stress-free start the
  // stress of a strain of 1e-6 (a millionth of the bulk modulus), so that a component held at zero
  // next to stresses of E·ε is not asked for a zero below their round-off (CVODE then stalled).
  const double stiffness_scale = 1e-6 * model.elasticity().at(mean_pressure(initial.stress)).K;
  const double stress_scale =
      std::max({initial.stress.cwiseAbs().maxCoeff(), initial.pc, 1.0, stiffness_scale});
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
  check(CVodeRootInit(s.memory, roots.n + 2, switching_function<Model>), "CVodeRootInit", problem);
  check(CVodeSetNoInactiveRootWarn(s.memory), "CVodeSetNoInactiveRootWarn", problem);
}

/// Restarts CVODE at (t, y) on the branch problem.active, with that branch's root directions; on
/// the apex branch, from the apex stress exactly.
template <class Model>
void restart(Solver& s, Problem<Model>& problem, sunrealtype t, const CvodeOptions& options, Roots& roots) {
  if (problem.active == kApexBranch) {
    double* y = N_VGetArrayPointer(s.y);
    const Model model = model_at(problem, y);
    if (const auto apex = held_apex(model, *problem.leg, problem.part, stress_from_voigt(stress_of(y)),
                                    y[kPc], dilation_of(model, y), options.surface_tolerance))
      Eigen::Map<Vec6>{y} = stress_to_voigt(*apex);
  }
  set_directions(roots.directions_used(), problem.active, roots.n);
  check(CVodeReInit(s.memory, t, s.y), "CVodeReInit", problem);
  check(CVodeSetRootDirection(s.memory, roots.directions.data()), "CVodeSetRootDirection", problem);
}

/// Starts `leg` from the state in s.y at pseudo-time 0: a drained leg's pore pressure dissipated,
/// the flowing surfaces decided at the start.
template <class Model>
void start_leg(Solver& s, Problem<Model>& problem, const Leg& leg, const CvodeOptions& options,
               Roots& roots) {
  double* y = N_VGetArrayPointer(s.y);
  problem.leg = &leg;
  problem.part = Partition(leg);
  if (!leg.undrained) y[kPorePressure] = 0.0;  // drainage open: the excess has dissipated
  const Model model = model_at(problem, y);
  problem.active = active_at_start(model, leg, problem.part, stress_of(y), y[kPc], dilation_of(model, y),
                                   options.surface_tolerance);
  restart(s, problem, 0.0, options, roots);
}

/// At a root of the switching functions: p_c onto the softening bound, the dilation onto the
/// cut-off, or the flowing surfaces switched; then CVODE restarted there.
template <class Model>
void switch_branch(Solver& s, Problem<Model>& problem, sunrealtype t, const CvodeOptions& options,
                   Roots& roots) {
  double* y = N_VGetArrayPointer(s.y);
  const Model model = model_at(problem, y);
  const int n = roots.n;
  roots.found.fill(0);
  check(CVodeGetRootInfo(s.memory, roots.found.data()), "CVodeGetRootInfo", problem);
  if (roots.found[n] != 0) {
    // Softening reached the bound: p_c onto it exactly, where the model's rate is 0, and on.
    y[kPc] = softening_bound(model);
  } else if (roots.found[n + 1] != 0) {
    // Dilation reached the cut-off: onto it exactly, where the ψ = 0 twin flows on.
    y[kDilation] = cutoff_of(model);
  } else {
    problem.active =
        active_at_root(model, *problem.leg, problem.part, stress_of(y), y[kPc], dilation_of(model, y),
                       options.surface_tolerance, problem.active, roots.found_used());
  }
  restart(s, problem, t, options, roots);
}

/// Integrates from t to the output time `k` (pseudo-time in increments of the leg), switching the
/// branch at each root so that no step straddles a kink.
template <class Model>
void advance_to(Solver& s, Problem<Model>& problem, sunrealtype& t, int k, const CvodeOptions& options,
                Roots& roots) {
  for (int switches = 0;; ++switches) {
    if (k - t <= kTooClose) {
      // A root a hair before the output time (e.g. reloading to the previous turning point, which
      // falls on an increment): CVODE cannot start on such an interval, and one Euler step over it
      // is exact to (k − t)² ≤ 1e-18 of an increment.
      if (right_hand_side<Model>(t, s.y, s.rates, &problem) != 0)
        throw std::runtime_error("cvode reference: " + problem.last_error);
      N_VLinearSum(1.0, s.y, k - t, s.rates, s.y);
      t = k;
      check(CVodeReInit(s.memory, t, s.y), "CVodeReInit", problem);
      return;
    }
    problem.last_error.clear();
    const int flag = CVode(s.memory, k, s.y, &t, CV_NORMAL);
    check(flag, "CVode", problem);
    if (flag != CV_ROOT_RETURN) return;
    if (switches > 100)
      throw std::runtime_error("cvode reference: more than 100 branch switches in one increment");
    switch_branch(s, problem, t, options, roots);
  }
}

/// The sample of the ODE state y.
template <class Model>
PointSample sample_of(const Problem<Model>& problem, const double* y) {
  PointSample sample;
  sample.strain = strain_from_voigt(Eigen::Map<const Vec6>(y + kStrain));
  sample.state.stress = stress_from_voigt(stress_of(y));
  sample.state.pc = y[kPc];
  sample.state.plastic_dilation = dilation_of(*problem.model, y);
  sample.state.volumetric_strain = problem.initial_volumetric_strain + sample.strain.trace();
  sample.pore_pressure = y[kPorePressure];
  return sample;
}

template <class Model>
PointHistory integrate_legs(const Model& model, const State& initial, std::span<const Leg> legs,
                            const CvodeOptions& options) {
  PointHistory history{{Mat3::Zero(), initial}};
  if (legs.empty()) return history;
  Problem<Model> problem{&model, &legs[0], Partition(legs[0]), 0, {}, initial.volumetric_strain};
  Roots roots;
  roots.n = surface_count(model);
  Solver s;
  open_solver(s, problem, initial, options, roots);
  std::size_t leg_index = 0;
  int increment = 0;  // of the current leg, from 0: where a failure is reported
  try {
    for (const Leg& given : legs) {
      const Leg leg = resolve_leg(given, history.back());
      increment = 0;
      start_leg(s, problem, leg, options, roots);
      sunrealtype t = 0.0;
      for (int k = 1; k <= leg.increments; ++k) {
        advance_to(s, problem, t, k, options, roots);
        history.push_back(sample_of(problem, N_VGetArrayPointer(s.y)));
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
  if (!has_rate_form(material))
    throw std::invalid_argument(std::string("the CVODE reference integrates a model's rate equations, which a ") +
                                std::string(model_name(material)) +
                                " material does not expose (use its own update: an integrator other than cvode)");
  return std::visit([&](const auto& model) { return integrate_legs(model, initial, legs, options); },
                    material);
}

}  // namespace soilsph::verification
