#include "constitutive/models/umat.h"

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

#include "constitutive/models/umat_crash_guard.h"
#include "constitutive/rotation.h"
#include "constitutive/tangent.h"

namespace soilsph {

namespace {

/// The Abaqus UMAT signature as gfortran compiles it: every argument by reference, then the hidden
/// length of CMNAME (size_t since gfortran 8). KSTEP points to an array of 4 (some UMATs declare
/// KSTEP(4)).
extern "C" {
using UmatFunction = void(double* stress, double* statev, double* ddsdde, double* sse, double* spd,
                          double* scd, double* rpl, double* ddsddt, double* drplde, double* drpldt,
                          const double* stran, const double* dstran, const double* time, const double* dtime,
                          const double* temp, const double* dtemp, const double* predef, const double* dpred,
                          const char* cmname, const int* ndi, const int* nshr, const int* ntens,
                          const int* nstatv, const double* props, const int* nprops, const double* coords,
                          const double* drot, double* pnewdt, const double* celent, const double* dfgrd0,
                          const double* dfgrd1, const int* noel, const int* npt, const int* layer,
                          const int* kspt, const int* kstep, const int* kinc, std::size_t cmname_length);
/// Optional: the PROPS length the library expects for a CMNAME (80 characters), −1 for a name it
/// does not know. A library that exports it gets its `props` length checked when it is loaded.
using DeclaredPropsFunction = int(const char* cmname, std::size_t cmname_length);
}

/// PNEWDT before each call: Abaqus sets it to a large value, which a UMAT may lower.
constexpr double kLargePnewdt = 1e36;

}  // namespace

/// One loaded shared library and its entry point, shared by every copy of a model that names it.
class UmatLibrary {
 public:
  UmatLibrary(const std::string& path, const std::string& symbol) : path_(path), symbol_(symbol) {
    handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw ParameterError("library = \"" + path + "\" cannot be loaded: " + dlerror());
    function_ = reinterpret_cast<UmatFunction*>(dlsym(handle_, symbol.c_str()));
    if (!function_) {
      dlclose(handle_);
      throw ParameterError("symbol = \"" + symbol + "\" is not exported by " + path +
                           " (gfortran names SUBROUTINE UMAT umat_; list the symbols with nm -D " + path +
                           ")");
    }
    declared_props_ = reinterpret_cast<DeclaredPropsFunction*>(dlsym(handle_, "soilsph_umat_nprops"));
  }
  UmatLibrary(const UmatLibrary&) = delete;
  UmatLibrary& operator=(const UmatLibrary&) = delete;
  ~UmatLibrary() { dlclose(handle_); }

  /// The library for (path, symbol), loaded once while any model holds it.
  static std::shared_ptr<UmatLibrary> open(const std::string& path, const std::string& symbol) {
    static std::mutex mutex;
    static std::map<std::pair<std::string, std::string>, std::weak_ptr<UmatLibrary>> loaded;
    const std::lock_guard lock(mutex);
    auto& slot = loaded[{path, symbol}];
    if (auto library = slot.lock()) return library;
    auto library = std::make_shared<UmatLibrary>(path, symbol);
    slot = library;
    return library;
  }

  UmatFunction* function() const { return function_; }
  DeclaredPropsFunction* declared_props() const { return declared_props_; }
  const std::string& path() const { return path_; }
  const std::string& symbol() const { return symbol_; }
  /// Held around a call of a UMAT that is not thread-safe.
  std::mutex& call_mutex() { return call_mutex_; }
  std::atomic<long>& fallbacks() { return fallbacks_; }

 private:
  std::string path_, symbol_;
  void* handle_ = nullptr;
  UmatFunction* function_ = nullptr;
  DeclaredPropsFunction* declared_props_ = nullptr;
  std::mutex call_mutex_;
  std::atomic<long> fallbacks_{0};
};

double pascals_per(StressUnit unit) {
  switch (unit) {
    case StressUnit::kPa:
      return 1e3;
    case StressUnit::MPa:
      return 1e6;
    case StressUnit::Pa:
      break;
  }
  return 1.0;
}

template <class Io>
void UmatParams::fields(const Io& io) {
  io.number("density", density, Range::positive(), "kg/m^3");
  io.file("library", library);
  io.text_or("symbol", symbol, Length::at_least(1));
  io.text_or("name", name, Length::at_most(kUmatNameLength));
  io.numbers_or("props", props, Range{});
  io.integer_or("state_variables", state_variables, 0, kMaxStateVariables);
  io.numbers_or("initial_state", initial_state, Range{},
                Count::none_or_exactly(static_cast<std::size_t>(state_variables), "state_variables"),
                Listed::WhenSet);
  io.choice_or("stress_unit", stress_unit, kStressUnitTable);
  io.boolean_or("thread_safe", thread_safe);
}
template void UmatParams::fields(const FieldDescriber&);
template void UmatParams::fields(const KeyLister&);

UmatParams UmatParams::read(const TableReader& t) {
  return read_fields<UmatParams>(t);
}

struct UmatModel::Outcome {
  State state;
  Mat6 tangent;  ///< DDSDDE in Pa
  double pnewdt;
};

UmatModel::UmatModel(const Params& params) : params_(validated(params, kName)) {
  library_ = UmatLibrary::open(params_.library, params_.symbol);
  install_umat_crash_guard();
  if (auto* declared = library_->declared_props()) {
    std::string cmname = params_.name;
    cmname.resize(kUmatNameLength, ' ');
    const int n = declared(cmname.data(), kUmatNameLength);
    if (n < 0)
      throw ParameterError("name = \"" + params_.name + "\" is not a material " + params_.library + " knows");
    if (static_cast<std::size_t>(n) != params_.props.size())
      throw ParameterError("props has " + std::to_string(params_.props.size()) + " values; " +
                           params_.library + " expects " + std::to_string(n) + " for name = \"" +
                           params_.name + "\"");
  }
  // The probe: one call with a zero strain increment from zero stress and the initial state
  // variables checks the call and gives the stiffness K = Σ_{i,j≤3} D_ij / 9, G = mean D_kk (k > 3,
  // engineering shears), the isotropic part of DDSDDE.
  try {
    probe_tangent_ = call(initial_state(Mat3::Zero()), Vec6::Zero(), Mat3::Identity(), UmatCall{}).tangent;
  } catch (const UmatError& e) {
    throw ParameterError(std::string("the probe call failed: ") + e.what());
  }
  const double K = probe_tangent_.topLeftCorner<3, 3>().sum() / 9.0;
  const double G = probe_tangent_.diagonal().tail<3>().mean();
  if (!(K > 0.0 && G > 0.0 && std::isfinite(K) && std::isfinite(G)))
    throw ParameterError(
        "the probe call's DDSDDE (zero strain increment from zero stress) has K = " + format_number(K) +
        " Pa, G = " + format_number(G) + " Pa: " + params_.library + ": " + params_.symbol +
        " must return a positive stiffness there (soilsph's first Newton guess and SPH time step "
        "use it)");
  probe_wave_modulus_ = probe_tangent_.diagonal().maxCoeff();
  const double E = 9.0 * K * G / (3.0 * K + G), nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  elasticity_ = Elasticity::constant(E, nu);
}

State UmatModel::initial_state(const Mat3& stress) const {
  State s;
  s.stress = stress;
  std::copy(params_.initial_state.begin(), params_.initial_state.end(), s.umat.statev.begin());
  return s;
}

std::string UmatModel::describe_call(const State& state, const UmatCall& call) const {
  std::ostringstream out;
  out << params_.library << ": " << params_.symbol << " (CMNAME \"" << params_.name
      << "\"), call KINC = " << state.umat.increment + 1 << ", NOEL = " << call.element
      << ", TIME = " << state.umat.time << ", DTIME = " << call.time_increment << ": ";
  return out.str();
}

UmatModel::Outcome UmatModel::call(const State& state, const Vec6& strain_increment, const Mat3& rotation,
                                   const UmatCall& where) const {
  // A state no UMAT has updated yet (KINC 0) starts from the initial state variables.
  State from = state;
  if (state.umat.increment == 0)
    std::copy(params_.initial_state.begin(), params_.initial_state.end(), from.umat.statev.begin());
  const double unit = pascals_per(params_.stress_unit);
  Vec6 stress = stress_to_voigt(from.stress) / unit;
  std::array<double, kMaxStateVariables + 1> statev{};
  std::copy(from.umat.statev.begin(), from.umat.statev.end(), statev.begin());
  Mat6 ddsdde = Mat6::Zero();
  double sse = 0.0, spd = 0.0, scd = 0.0, rpl = 0.0, drpldt = 0.0;
  double ddsddt[6] = {}, drplde[6] = {};
  const double temp = 0.0, dtemp = 0.0, predef[1] = {}, dpred[1] = {};
  const double time[2] = {from.umat.time, from.umat.time};
  const double dtime = where.time_increment;
  const Vec6 dstran = strain_increment;
  const Vec6 stran = Eigen::Map<const Vec6>(from.umat.strain.data());
  const int ndi = 3, nshr = 3, ntens = 6, nstatv = params_.state_variables;
  const int nprops = static_cast<int>(params_.props.size());
  const double dummy_props[1] = {};
  const double* props = params_.props.empty() ? dummy_props : params_.props.data();
  double pnewdt = kLargePnewdt;
  const double celent = where.characteristic_length;
  // The small-strain deformation gradients I + ε_n and I + ε_n + Δε (no rotation part is tracked).
  const Mat3 dfgrd0 = Mat3::Identity() + strain_from_voigt(stran);
  const Mat3 dfgrd1 = dfgrd0 + strain_from_voigt(dstran);
  const int noel = where.element, npt = where.point, layer = 1, kspt = 1;
  const int kstep[4] = {1, 1, 0, 0};  // step 1, static procedure, NLGEOM off, no linear perturbation
  const int kinc = from.umat.increment + 1;
  char cmname[kUmatNameLength];
  std::fill(std::begin(cmname), std::end(cmname), ' ');
  std::copy(params_.name.begin(), params_.name.end(), cmname);

  auto umat = [&] {
    library_->function()(stress.data(), statev.data(), ddsdde.data(), &sse, &spd, &scd, &rpl, ddsddt, drplde,
                         &drpldt, stran.data(), dstran.data(), time, &dtime, &temp, &dtemp, predef, dpred,
                         cmname, &ndi, &nshr, &ntens, &nstatv, props, &nprops, where.coordinates.data(),
                         rotation.data(), &pnewdt, &celent, dfgrd0.data(), dfgrd1.data(), &noel, &npt, &layer,
                         &kspt, kstep, &kinc, kUmatNameLength);
  };
  const UmatCallSite site{.library = library_->path().c_str(),
                          .symbol = library_->symbol().c_str(),
                          .name = params_.name.c_str(),
                          .increment = kinc,
                          .element = noel,
                          .time = from.umat.time,
                          .time_increment = dtime};
  int crash = 0;
  {
    std::unique_lock<std::mutex> lock;
    if (!params_.thread_safe) lock = std::unique_lock(library_->call_mutex());
    crash = guarded_umat_call(
        site, [](void* f) { (*static_cast<decltype(umat)*>(f))(); }, &umat);
  }
  if (crash != 0)
    throw UmatError(describe_call(from, where) + "crashed with " + describe_signal(crash) +
                    " inside the call (the library's own fault: run the UMAT under a debugger, or with "
                    "gfortran -g -fcheck=all, from this state)");

  Outcome out{from, ddsdde * unit, pnewdt};
  if (pnewdt < 1.0) return out;  // the caller retries with half the increment
  if (!stress.allFinite()) throw UmatError(describe_call(from, where) + "returned a non-finite STRESS");
  for (int k = 0; k < nstatv; ++k)
    if (!std::isfinite(statev[k]))
      throw UmatError(describe_call(from, where) + "returned a non-finite STATEV(" + std::to_string(k + 1) +
                      ")");
  State& next = out.state;
  next.stress = stress_from_voigt(stress * unit);
  std::copy(statev.begin(), statev.begin() + kMaxStateVariables, next.umat.statev.begin());
  Eigen::Map<Vec6>(next.umat.strain.data()) = stran + dstran;
  next.umat.time = from.umat.time + dtime;
  next.umat.increment = kinc;
  next.plastic_multiplier = 0.0;
  return out;
}

State UmatModel::advance(const State& state, const Vec6& strain_increment, const Mat3& rotation,
                         const UmatCall& where, int halvings, Mat6* tangent) const {
  const Outcome outcome = call(state, strain_increment, rotation, where);
  if (outcome.pnewdt >= 1.0) {
    if (tangent) *tangent = outcome.tangent;
    return outcome.state;
  }
  if (halvings == kMaxUmatHalvings)
    throw UmatError(describe_call(state, where) +
                    "asked for a smaller increment (PNEWDT = " + format_number(outcome.pnewdt) + ") after " +
                    std::to_string(kMaxUmatHalvings) + " halvings of the increment");
  UmatCall half = where;
  half.time_increment *= 0.5;
  const State middle = advance(state, 0.5 * strain_increment, rotation, half, halvings + 1, nullptr);
  return advance(middle, 0.5 * strain_increment, Mat3::Identity(), half, halvings + 1, tangent);
}

State UmatModel::update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment,
                        const UmatCall& where) const {
  if (spin_increment.isZero(0.0))
    return advance(state, strain_to_voigt(strain_increment), Mat3::Identity(), where, 0, nullptr);
  // Abaqus rotates the stress and STRAN by the increment's rotation before the call and passes it as
  // DROT for the UMAT's own tensors; the stress rotation is the built-in models' (rotation.h).
  State rotated = rotate_state(state, spin_increment);
  const Mat3 Q = spin_rotation(spin_increment);
  const Mat3 strain = Q * strain_from_voigt(Eigen::Map<const Vec6>(state.umat.strain.data())) * Q.transpose();
  Eigen::Map<Vec6>(rotated.umat.strain.data()) = strain_to_voigt(strain);
  return advance(rotated, strain_to_voigt(strain_increment), Q, where, 0, nullptr);
}

Mat6 UmatModel::returned_tangent(const State& state, const Mat3& strain_increment) const {
  Mat6 tangent = Mat6::Zero();
  advance(state, strain_to_voigt(strain_increment), Mat3::Identity(), UmatCall{}, 0, &tangent);
  return tangent;
}

Mat6 UmatModel::consistent_tangent(const State& state, const Mat3& strain_increment) const {
  if (params_.tangent == UmatTangent::FiniteDifference)
    return finite_difference_tangent(*this, state, strain_increment);
  const Mat6 tangent = returned_tangent(state, strain_increment);
  if (tangent.allFinite() && !tangent.isZero(0.0)) return tangent;
  ++library_->fallbacks();
  const Mat6 differences = finite_difference_tangent(*this, state, strain_increment);
  if (differences.isZero(0.0))
    throw UmatError(
        describe_call(state, UmatCall{}) +
        "returned an unusable DDSDDE (not finite or all zero) and the stress does not respond to the "
        "strain increment either");
  return differences;
}

double UmatModel::wave_modulus(const State& state, const UmatCall& where) const {
  UmatCall now = where;
  now.time_increment = 0.0;
  try {
    const Outcome zero = call(state, Vec6::Zero(), Mat3::Identity(), now);
    const double stiffest = zero.tangent.diagonal().maxCoeff();
    if (std::isfinite(stiffest)) return std::max(stiffest, probe_wave_modulus_);
  } catch (const UmatError&) {
  }
  return probe_wave_modulus_;
}

long UmatModel::fallback_count() const {
  return library_->fallbacks().load();
}

std::string UmatModel::describe_constants() const {
  std::ostringstream out;
  const Moduli D = elasticity_.at(0.0);
  out << "  library = " << params_.library << ", symbol = " << params_.symbol << ", CMNAME = \""
      << params_.name << "\"\n  NPROPS = " << params_.props.size() << ", NSTATV = " << params_.state_variables
      << ", stress unit " << name_of(kStressUnitTable, params_.stress_unit) << '\n'
      << "  probe call (zero strain increment from zero stress): K = " << D.K << " Pa, G = " << D.G << " Pa\n"
      << "  calls "
      << (params_.thread_safe ? "may run concurrently (thread_safe = true)"
                              : "are serialised (thread_safe = false)")
      << '\n';
  return out.str();
}

}  // namespace soilsph
