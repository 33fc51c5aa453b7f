#pragma once
/// @file
/// OpenGeoSys's semi-explicit Modified Cam-Clay scheme at one point of a homogeneous triaxial test,
/// written out from its MFront behaviours so that a test can (1) reproduce OpenGeoSys's stored results
/// on OpenGeoSys's own time grid, which shows that the definitions below are OpenGeoSys's, and (2) run
/// the same scheme on a finer grid, which removes OpenGeoSys's time-discretisation error from its
/// stored numbers before they are compared with soilsph's integrators.
///
/// Sources (ufz/ogs, commit 06582d1aa8d320c2a98e80e1ba79fbe47d23bd3a unless said otherwise):
///   MaterialLib/SolidModels/MFront/ModCamClay_semiExplParaInitNLnu_inc.mfront ("original": K = v0 p/κ
///     from the step's start, G = 3K(1−2ν)/(2(1+ν)), hardening exponent v0/(λ−κ), v += v0 tr Δε,
///     no ambient pressure, p_c,min = 0.5e-8 p_c0);
///   MaterialLib/SolidModels/MFront/ModCamClay_semiExpl_constE.mfront, commit
///     72202334bedd087beae7f25b8ce23d15dce0eed0 ("constE": constant E and ν, ambient pressure
///     p_amb = 1 kPa added to p in the yield function and the flow direction, hardening exponent
///     v/(λ−κ) with v from the step's start, v *= exp(tr Δε), p_c,min = 1e-15 p_c0).
/// In both, a step under imposed stress σ_{n+1} (every component imposed: the stress field of the
/// triaxial test is homogeneous) is
///   Δε^e = D(p_n)⁻¹ (σ_{n+1} − σ_n)                          (@ComputeFinalStress: σ = σ0 + D Δε^e)
///   p_c,n+1 from f(σ_{n+1}, p_c,n+1) = q² + M² p̃ (p̃ − p_c) = 0, p̃ = p + p_amb   (flp = f/fchar = 0)
///   Δε_V^p = −(p_c,n+1 − p_c,n) / (θ (p_c,n+1 − p_c,min)),  θ = v/(λ−κ)           (frpc = 0)
///   Δε^p = Δλ n, n ∝ 3s − (M²(2p̃ − p_c)/3) I at the step's end, so the plastic deviator is
///   Δε_V^p · 3s / (−M²(2p̃ − p_c,n+1)) and Δλ = |Δε^p| (EquivalentPlasticStrain sums it),
/// with tension-positive stresses and strains and p, p_c compression-positive.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace soilsph::test {

/// Principal components (axial, radial, hoop) of a triaxial stress or strain, tension-positive.
using Triaxial = Eigen::Vector3d;

struct OgsCamClayScheme {
  double M, lambda, kappa, nu, v0, pc0;
  double ambient_pressure = 0.0;    ///< p_amb, Pa
  double pc_min = 0.0;              ///< p_c,min, Pa
  double young_modulus = 0.0;       ///< constant E (Pa); 0: K = v0 p/κ from the step's start
  bool current_volume = false;      ///< θ = v/(λ−κ) (v at the step's start) instead of v0/(λ−κ)
  bool exponential_volume = false;  ///< v *= exp(tr Δε) instead of v += v0 tr Δε
};

struct OgsPointState {
  Triaxial strain = Triaxial::Zero();
  double v = 0.0;               ///< VolumeRatio
  double pc = 0.0;              ///< PreConsolidationPressure, Pa
  double plastic_volume = 0.0;  ///< PlasticVolumetricStrain (tension-positive)
  double plastic_path = 0.0;    ///< EquivalentPlasticStrain, Σ |Δε^p|

  double strain_norm() const {  // the magnitude VTK writes as the range of `epsilon`
    return std::sqrt(strain(0) * strain(0) + strain(1) * strain(1) + strain(2) * strain(2));
  }
  double eps_v() const { return -strain.sum(); }  ///< compression-positive
  double eps_q() const { return 2.0 / 3.0 * (strain(1) - strain(0)); }
};

/// The scheme over the time grid `times` (ascending, after t = 0) under the stress history `stress`,
/// from the stress at t = 0 with p_c = p_c0 and v = v0.
inline OgsPointState run_ogs_scheme(const OgsCamClayScheme& m, const std::vector<double>& times,
                                    const std::function<Triaxial(double)>& stress) {
  OgsPointState s{.v = m.v0, .pc = m.pc0};
  Triaxial sigma = stress(0.0);
  const auto mean_pressure = [](const Triaxial& x) { return -x.sum() / 3.0; };
  for (double t : times) {
    const Triaxial next = stress(t);
    // Elastic strain with the moduli at the step's start.
    const double K = m.young_modulus > 0.0 ? m.young_modulus / (3.0 * (1.0 - 2.0 * m.nu))
                                           : m.v0 / m.kappa * mean_pressure(sigma);
    const double G = 1.5 * K * (1.0 - 2.0 * m.nu) / (1.0 + m.nu);
    const Triaxial d_sigma = next - sigma;
    const double d_mean = d_sigma.sum() / 3.0;
    Triaxial d_strain =
        (d_sigma.array() - d_mean).matrix() / (2.0 * G) + Triaxial::Constant(d_mean / (3.0 * K));
    // Plastic strain: p_c from the yield condition at the step's end, when it grows.
    const double p = mean_pressure(next) + m.ambient_pressure;
    const Triaxial dev = (next.array() + mean_pressure(next)).matrix();
    const double q2 = 1.5 * dev.squaredNorm();
    const double pc_yield = p + q2 / (m.M * m.M * p);
    if (pc_yield > s.pc) {
      const double theta = (m.current_volume ? s.v : m.v0) / (m.lambda - m.kappa);
      const double dv_plastic = -(pc_yield - s.pc) / (theta * (pc_yield - m.pc_min));
      const Triaxial d_plastic =
          Triaxial::Constant(dv_plastic / 3.0) + dv_plastic * 3.0 * dev / (-m.M * m.M * (2.0 * p - pc_yield));
      s.pc = pc_yield;
      s.plastic_volume += dv_plastic;
      s.plastic_path += d_plastic.norm();
      d_strain += d_plastic;
    }
    s.strain += d_strain;
    s.v = m.exponential_volume ? s.v * std::exp(d_strain.sum()) : s.v + m.v0 * d_strain.sum();
    sigma = next;
  }
  return s;
}

/// `times` with each step split into `parts` equal steps.
inline std::vector<double> refined(const std::vector<double>& times, int parts) {
  std::vector<double> out;
  double previous = 0.0;
  for (double t : times) {
    for (int j = 1; j < parts; ++j) out.push_back(previous + (t - previous) * j / parts);
    out.push_back(t);
    previous = t;
  }
  return out;
}

}  // namespace soilsph::test
