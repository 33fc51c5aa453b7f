// libsoilsph_umat.so: soilsph's Drucker–Prager, Mohr–Coulomb and Modified Cam-Clay behind the Abaqus
// UMAT interface (gfortran's calling convention: `umat_`, every argument by reference, the hidden
// length of CMNAME last), the reverse of models/umat.h over the same model classes. CMNAME chooses
// the model, optionally with soilsph's integrator after a colon ("MODIFIED-CAM-CLAY:explicit"; case
// is ignored); PROPS and STATEV as tabled in docs/reference/umat-library.md. Stresses are in Pa,
// tension-positive, Voigt 11, 22, 33, 12, 13, 23 with engineering shear strains; the stress arrives
// rotated (the caller's job in Abaqus) and DDSDDE is the model's algorithmic tangent
// (constitutive/tangent.h).
#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "constitutive/models/drucker_prager.h"
#include "constitutive/models/modified_cam_clay.h"
#include "constitutive/models/mohr_coulomb.h"
#include "constitutive/tangent.h"

namespace soilsph {
namespace {

using ExportedModel = std::variant<DruckerPrager, MohrCoulomb, ModifiedCamClay>;
constexpr int kStateVariables = 4;  ///< p_c, equivalent plastic strain, plastic volumetric strain, Δλ

/// CMNAME without its blank padding, in lower case: the model's name and, after ':', an integrator.
std::string trimmed_lower(const char* cmname, std::size_t length) {
  std::string name(cmname, length);
  name.erase(name.find_last_not_of(' ') + 1);
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name;
}

/// The PROPS length of a model's name, or −1.
int props_of(const std::string& model) {
  if (model == DruckerPrager::kName || model == MohrCoulomb::kName) return 5;
  if (model == ModifiedCamClay::kName) return 7;
  return -1;
}

template <class Params>
void set_frictional(Params& p, const double* props, Integrator integrator) {
  p.density = 1.0;  // not used by the update; a UMAT caller keeps its own density
  p.young_modulus = props[0], p.poisson_ratio = props[1], p.friction_angle = props[2];
  p.cohesion = props[3], p.dilatancy_angle = props[4];
  p.integrator = integrator;
}

/// The model CMNAME and PROPS describe (built once per thread while they stay the same: the
/// constructors validate and derive constants).
const ExportedModel& model_for(const std::string& name, const double* props, int nprops) {
  thread_local std::string last_name;
  thread_local std::vector<double> last_props;
  thread_local std::optional<ExportedModel> model;
  if (model && name == last_name && std::equal(props, props + nprops, last_props.begin(), last_props.end()))
    return *model;
  const std::size_t colon = name.find(':');
  const std::string kind = name.substr(0, colon);
  const int expected = props_of(kind);
  if (expected < 0) throw std::invalid_argument("CMNAME \"" + name + "\" names no model of libsoilsph_umat");
  if (nprops != expected)
    throw std::invalid_argument("CMNAME \"" + name + "\" takes " + std::to_string(expected) + " PROPS, not " +
                                std::to_string(nprops));
  Integrator integrator = Integrator::Implicit;
  if (colon != std::string::npos) integrator = parse_integrator(name.substr(colon + 1));
  if (kind == DruckerPrager::kName) {
    DruckerPrager::Params p;
    set_frictional(p, props, integrator);
    model.emplace(DruckerPrager(p));
  } else if (kind == MohrCoulomb::kName) {
    MohrCoulomb::Params p;
    set_frictional(p, props, integrator);
    model.emplace(MohrCoulomb(p));
  } else {
    ModifiedCamClay::Params p;
    p.density = 1.0;
    p.poisson_ratio = props[0], p.friction_angle = props[1], p.compression_index = props[2];
    p.swelling_index = props[3], p.initial_void_ratio = props[4];
    if (props[5] > 0.0) p.elasticity = Elasticity::Kind::Constant, p.young_modulus = props[5];
    if (props[6] > 0.0) p.elastic_pressure_floor = props[6];
    p.integrator = integrator;
    model.emplace(ModifiedCamClay(p));
  }
  last_name = name;
  last_props.assign(props, props + nprops);
  return *model;
}

}  // namespace
}  // namespace soilsph

extern "C" {

/// The PROPS length for a CMNAME, −1 for a name this library does not know: soilsph checks a
/// `props` array against it when it loads the library (models/umat.h).
__attribute__((visibility("default"))) int soilsph_umat_nprops(const char* cmname, std::size_t length) {
  const std::string name = soilsph::trimmed_lower(cmname, length);
  return soilsph::props_of(name.substr(0, name.find(':')));
}

__attribute__((visibility("default"))) void umat_(
    double* stress, double* statev, double* ddsdde, double* /*sse*/, double* /*spd*/, double* /*scd*/,
    double* /*rpl*/, double* /*ddsddt*/, double* /*drplde*/, double* /*drpldt*/, const double* /*stran*/,
    const double* dstran, const double* /*time*/, const double* /*dtime*/, const double* /*temp*/,
    const double* /*dtemp*/, const double* /*predef*/, const double* /*dpred*/, const char* cmname,
    const int* /*ndi*/, const int* /*nshr*/, const int* ntens, const int* nstatv, const double* props,
    const int* nprops, const double* /*coords*/, const double* /*drot*/, double* pnewdt,
    const double* /*celent*/, const double* /*dfgrd0*/, const double* /*dfgrd1*/, const int* /*noel*/,
    const int* /*npt*/, const int* /*layer*/, const int* /*kspt*/, const int* /*kstep*/, const int* /*kinc*/,
    std::size_t cmname_length) {
  using namespace soilsph;
  // Anything this library cannot do (a name it does not know, a PROPS or NTENS it cannot use, an
  // update that fails) asks the caller for a smaller increment, which it cannot satisfy: soilsph and
  // Abaqus then stop with their own message. An exception must not cross into Fortran.
  if (*ntens != 6 || *nstatv < kStateVariables) {
    *pnewdt = 0.0;
    return;
  }
  try {
    const ExportedModel& model = model_for(trimmed_lower(cmname, cmname_length), props, *nprops);
    State state;
    state.stress = stress_from_voigt(Eigen::Map<const Vec6>(stress));
    state.pc = statev[0], state.plastic_shear_strain = statev[1], state.plastic_dilation = statev[2];
    state.plastic_multiplier = statev[3];
    const Mat3 increment = strain_from_voigt(Eigen::Map<const Vec6>(dstran));
    std::visit(
        [&](const auto& m) {
          // STATEV(1) = 0 at the start of a clay: normally consolidated, on the yield surface through σ.
          if (m.kHasPreconsolidation && state.pc <= 0.0)
            state.pc = m.initial_preconsolidation(state.stress, 1.0);
          // A zero strain increment asks for the tangent at the state (the probe call): the elastic one.
          if (increment.isZero(0.0)) {
            Eigen::Map<Mat6> tangent(ddsdde);
            const Moduli D = m.elasticity().at(mean_pressure(state.stress));
            tangent = voigt_isotropic_stiffness(D.K, D.G);
            return;
          }
          const State next = m.update(state, increment, Mat3::Zero());
          Eigen::Map<Mat6> tangent(ddsdde);
          Eigen::Map<Vec6> updated(stress);
          tangent = algorithmic_tangent(m, state, increment);
          updated = stress_to_voigt(next.stress);
          statev[0] = next.pc, statev[1] = next.plastic_shear_strain, statev[2] = next.plastic_dilation;
          statev[3] = next.plastic_multiplier;
        },
        model);
  } catch (const std::exception&) {
    *pnewdt = 0.0;
  }
}

}  // extern "C"
