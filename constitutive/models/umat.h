#pragma once
/// @file
/// A UMAT plug-in: a model written to the Abaqus user-material interface, loaded from a shared
/// library, behind the same hooks as the built-in models (model_concept.h). The adapter maps
/// soilsph's state (full 3×3 tension-positive stress in Pa, a strain and a spin increment) to the
/// Abaqus call and back:
///   - NTENS = 6, NDI = NSHR = 3, Voigt order 11, 22, 33, 12, 13, 23, engineering shear strains,
///     tension positive, DDSDDE(6, 6) column-major (∂Δσ/∂Δε);
///   - the stress is rotated objectively before the call (constitutive/rotation.h, as for the
///     built-in models) and DROT is that increment's rotation, for the UMAT's own tensorial
///     state variables; STRAN is carried and rotated likewise;
///   - stresses and DDSDDE are scaled by `stress_unit` in and out; PROPS are the UMAT's own;
///   - PNEWDT < 1 cuts the increment in halves, up to kMaxUmatHalvings times, then an error;
///   - every failure (non-finite results, PNEWDT on every try) is a UmatError naming the library,
///     the symbol and the call (KINC, NOEL, TIME).
/// The conventions table: docs/guide/umat.md.
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "constitutive/elasticity.h"
#include "constitutive/models/perfect_plasticity.h"
#include "constitutive/parameters.h"
#include "constitutive/state.h"
#include "constitutive/voigt.h"

namespace soilsph {

/// CMNAME's length: a UMAT's material name is blank-padded to it in the call.
inline constexpr std::size_t kUmatNameLength = 80;

/// Halvings of an increment a UMAT may ask for with PNEWDT < 1 (down to 2⁻¹⁰ of it).
inline constexpr int kMaxUmatHalvings = 10;

/// A UMAT call that failed: the message names the library, the symbol and the call.
class UmatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The unit the UMAT's stresses are in.
enum class StressUnit { Pa, kPa, MPa };
inline constexpr auto kStressUnitTable = enum_table<StressUnit>({
    {StressUnit::Pa, "Pa"},
    {StressUnit::kPa, "kPa"},
    {StressUnit::MPa, "MPa"},
});
/// Pascals per unit.
double pascals_per(StressUnit unit);

/// Which tangent the point driver's Newton iteration uses.
enum class UmatTangent {
  Ddsdde,            ///< the UMAT's DDSDDE (central differences where it is unusable, counted)
  FiniteDifference,  ///< central differences of the UMAT's stress update
};
inline constexpr auto kUmatTangentTable = enum_table<UmatTangent>({
    {UmatTangent::Ddsdde, "ddsdde"},
    {UmatTangent::FiniteDifference, "finite-difference"},
});
inline constexpr auto kUmatTangentNames = names_of(kUmatTangentTable);

/// Where and when a call happens: what the caller knows besides the state (SPH: the particle).
struct UmatCall {
  int element = 1;                     ///< NOEL: the particle or test id
  int point = 1;                       ///< NPT
  double time_increment = 1.0;         ///< DTIME (s); at a point each increment is one unit of time
  double characteristic_length = 1.0;  ///< CELENT (m): the particle spacing, or 1 at a point
  Vec3 coordinates = Vec3::Zero();     ///< COORDS (m)
};

struct UmatParams {
  std::string library;  ///< the shared library (a path relative to the TOML file is resolved when read)
  std::string symbol = "umat_";
  std::string name;  ///< CMNAME (blank-padded to 80 characters in the call)
  std::vector<double> props;
  int state_variables = 0;            ///< NSTATV
  std::vector<double> initial_state;  ///< STATEV at the start (zeros when empty)
  StressUnit stress_unit = StressUnit::Pa;
  double density = 0.0;      ///< kg/m³
  bool thread_safe = false;  ///< whether calls may run concurrently (SAVE variables, unit 1 output: no)
  UmatTangent tangent = UmatTangent::Ddsdde;

  static UmatParams read(const TableReader& table);
  /// Every key of a `[material]` table with its allowed values and default, read, checked,
  /// described or listed by `io` (FieldReader, FieldChecker, FieldDescriber, KeyLister), in the
  /// order results list them. `tangent` is no key: `soilsph point --tangent` sets it.
  template <class Io>
  void fields(const Io& io);
};

class UmatLibrary;

/// The plug-in as a model: `update` is one Abaqus call (or its halves), `consistent_tangent` the
/// call's DDSDDE. The elasticity is the isotropic part of DDSDDE at the probe call (zero strain
/// increment from zero stress and the initial state variables): the first Newton guess of the point
/// driver and the SPH time step need a stiffness.
class UmatModel : public NoHardeningVariable {
 public:
  using Params = UmatParams;
  static constexpr std::string_view kName = "umat";

  /// Loads the library (once per path: copies share it), finds the symbol and makes the probe call;
  /// ParameterError for anything wrong.
  explicit UmatModel(const Params& params);

  const Params& params() const { return params_; }
  const Elasticity& elasticity() const { return elasticity_; }
  std::string describe_constants() const;
  /// The state a point or particle starts from: STATEV = initial_state.
  State initial_state(const Mat3& stress) const;

  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment) const {
    return update(state, strain_increment, spin_increment, UmatCall{});
  }
  State update(const State& state, const Mat3& strain_increment, const Mat3& spin_increment,
               const UmatCall& call) const;
  /// The tangent of update(state, strain_increment): DDSDDE, or central differences (params.tangent,
  /// or where DDSDDE is not finite or all zero: counted by fallback_count()).
  Mat6 consistent_tangent(const State& state, const Mat3& strain_increment) const;
  /// ρc² (Pa) for the SPH time step at `state`: the largest diagonal entry of the DDSDDE of a call
  /// with a zero strain increment and DTIME = 0 from it (the stiffness the next increment starts
  /// with; Anura3D bounds its critical time step by the same entry), and never less than the probe
  /// call's. A call that fails gives the probe's (the stress update that follows says why).
  double wave_modulus(const State& state, const UmatCall& where) const;
  /// How many tangents were central differences because DDSDDE was unusable.
  long fallback_count() const;
  /// The tangent as the UMAT returns it, for the tangent check (soilsph material --check-tangent).
  Mat6 returned_tangent(const State& state, const Mat3& strain_increment) const;

 private:
  struct Outcome;
  /// One call from `state` (already rotated) with DROT = `rotation`; no halving.
  Outcome call(const State& state, const Vec6& strain_increment, const Mat3& rotation,
               const UmatCall& call) const;
  /// The increment with PNEWDT answered by halving; `tangent` gets the last call's DDSDDE.
  State advance(const State& state, const Vec6& strain_increment, const Mat3& rotation, const UmatCall& call,
                int halvings, Mat6* tangent) const;
  std::string describe_call(const State& state, const UmatCall& call) const;

  Params params_;
  std::shared_ptr<UmatLibrary> library_;
  Elasticity elasticity_;
  Mat6 probe_tangent_ = Mat6::Zero();
  double probe_wave_modulus_ = 0.0;  ///< the largest diagonal entry of the probe's DDSDDE (Pa)
};

}  // namespace soilsph
