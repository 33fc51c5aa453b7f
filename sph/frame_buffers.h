#pragma once
/// @file
/// Fills the derived per-particle fields a Frame shows (stress components, p, q, plastic strain)
/// from the particles, into buffers reused from frame to frame, and returns the Frame view; fields
/// not selected for output are not computed.
#include <algorithm>
#include <vector>

#include "constitutive/material.h"
#include "sph/output/frame.h"
#include "sph/particles.h"
#include "sph/scene_settings.h"

namespace soilsph::sph {

/// How many STATEV the frames carry: with [output] state_variables the largest NSTATV of the scene's
/// UMAT materials, else none.
inline int frame_state_variables(const OutputSettings& output, const std::vector<Material>& materials) {
  int count = 0;
  if (output.state_variables)
    for (const Material& m : materials)
      if (const auto* umat = std::get_if<UmatModel>(&m))
        count = std::max(count, umat->params().state_variables);
  return count;
}

class FrameBuffers {
 public:
  /// A view of the soil particles of `p` at time t, in 2D or 3D (Frame::dimension). Only the derived
  /// fields in `fields` are computed; the spans of the others are empty (a FrameWriter with the same
  /// fields skips them).
  /// `state_variables` > 0: the first that many UMAT STATEV of every particle too (Frame).
  template <int dim>
  Frame view(const ParticlesOf<dim>& p, double t, FieldSet fields = FieldSet::all(),
             int state_variables = 0) {
    const std::size_t n = p.soil_count;
    const bool stress = fields.contains(Field::stress), mean = fields.contains(Field::p),
               mises = fields.contains(Field::q), plastic = fields.contains(Field::plastic_strain);
    for (auto* a : {&sxx_, &syy_, &szz_, &sxy_}) a->resize(stress ? n : 0);
    for (auto* a : {&sxz_, &syz_}) a->resize(stress && dim == 3 ? n : 0);
    p_.resize(mean ? n : 0);
    q_.resize(mises ? n : 0);
    plastic_.resize(plastic ? n : 0);
    for (std::size_t i = 0; i < n; ++i) {
      const State& s = p.state[i];
      if (stress) {
        sxx_[i] = s.stress(0, 0);
        syy_[i] = s.stress(1, 1);
        szz_[i] = s.stress(2, 2);
        sxy_[i] = s.stress(0, 1);
        if constexpr (dim == 3) sxz_[i] = s.stress(0, 2), syz_[i] = s.stress(1, 2);
      }
      if (mean) p_[i] = mean_pressure(s.stress);
      if (mises) q_[i] = deviatoric_stress(s.stress);
      if (plastic) plastic_[i] = s.plastic_shear_strain;
    }
    Frame f;
    f.dimension = dim;
    f.time = t;
    f.x = {p.x.data(), n};
    f.y = {p.y.data(), n};
    f.vx = {p.vx.data(), n};
    f.vy = {p.vy.data(), n};
    f.sxx = sxx_, f.syy = syy_, f.szz = szz_, f.sxy = sxy_;
    if constexpr (dim == 3) {
      f.z = {p.z.data(), n};
      f.vz = {p.vz.data(), n};
      f.sxz = sxz_, f.syz = syz_;
    }
    f.p = p_, f.q = q_;
    f.plastic_strain = plastic_;
    f.density = {p.density.data(), n};
    f.layer = p.layer;
    f.material = p.material;
    statev_.resize(static_cast<std::size_t>(state_variables) * n);
    for (std::size_t k = 0; k < static_cast<std::size_t>(state_variables); ++k)
      for (std::size_t i = 0; i < n; ++i) statev_[k * n + i] = p.state[i].umat.statev[k];
    f.state_variables = statev_;
    f.state_variable_count = state_variables;
    f.id = p.id;
    return f;
  }

 private:
  std::vector<double> sxx_, syy_, szz_, sxy_, sxz_, syz_, p_, q_, plastic_, statev_;
};

}  // namespace soilsph::sph
