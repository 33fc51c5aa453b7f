#pragma once
/// @file
/// The ghosts behind symmetry planes: the soil's exact mirror images. A symmetry plane stands for
/// the mirror half of the problem, so what lies behind it is the soil itself, reflected: image b of
/// soil particle j sits at x_j reflected across the plane, moves with j, and carries j's mass and
/// density, its velocity and stress reflected. Ghosts on a fixed lattice (stages/boundaries.h),
/// which average the soil around them, would also stand where the mirror half holds no soil: beside
/// a heap's free surface, where a lattice ghost next to the apex particle acts as a full-mass copy
/// of it, so that the apex has about twice the neighbours of its exact mirror, far too low a
/// density rate, and blows up (docs/method/geometry-3d.md, "Symmetry planes").
///
/// The planes are normal to an axis, so a reflection flips one coordinate about the plane's offset
/// o_a, x_a → 2 o_a − x_a, and the image across the planes of a set S of distinct axes has a sign
/// s_a = −1 for a ∈ S and +1 else:
///   position  s∘x_j + shift,  shift_a = 2 o_a for a ∈ S, 0 else
///   velocity  s∘v_j,   stress  s_a s_b σ_j,ab,   mass m_j,   density ρ_j
/// which leaves the normal velocity mirrored and the shear stress on the plane mirrored: free slip.
///
/// The images are rebuilt at each neighbour search, from the soil's positions there. Every soil
/// particle within the reach of a plane gets an image across it; where planes meet, one across
/// each set of them whose distances d_k from the particle have √(Σ d_k²) within the reach (the
/// image's distance from the line or corner they make). For the soil's rows the search radius
/// R = 2h + s (neighbours/neighbour_list.h) is enough: until the next search every particle moves
/// less than s/2, so a soil particle i and the image of j across S stay at least
/// √(Σ_{k∈S} (d_i,k + d_j,k)²) ≥ √(Σ d_j,k²) > R − s/2 > 2h apart if j was left out. A ghost behind
/// a plane takes the images into its kernel average as the soil they stand for (its row lists them,
/// neighbours/neighbour_list.h), so the reach is R plus the ghost layers' corner diagonal
/// (setup_parts.h, image_reach). In order of the soil particle's id, then of the set of planes (a
/// bit mask over them): the rows, hence the sums, depend neither on the thread count nor on the
/// order the soil is stored in.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "sph/neighbours/cell_list.h"
#include "sph/particles.h"
#include "sph/stages/pair_vectors.h"
#include "sph/stages/velocity_gradient.h"

namespace soilsph::sph {

/// A symmetry plane x_axis = offset, the soil on the side where side · (x_axis − offset) > 0.
struct SymmetryPlane {
  int axis;
  double offset;  ///< m
  double side;    ///< +1 or −1
  int wall;       ///< the wall's index (ParticlesOf::wall_id of its images)
};

template <int dim>
class MirrorImagesOf {
 public:
  MirrorImagesOf() = default;
  /// The images across `planes` of the soil within `reach` (m) of them (setup_parts.h, image_reach).
  MirrorImagesOf(std::vector<SymmetryPlane> planes, double reach) : planes_(std::move(planes)), reach_(reach) {}

  bool any() const { return !planes_.empty(); }

  /// Replaces p's images [image_begin, size()) by those of the soil at `soil` (positions of the
  /// soil particles, the neighbour search's), placed (place()) where the soil is now, with its mass
  /// and density, their wall attributes those of their first plane (serial).
  void rebuild(ParticlesOf<dim>& p, const Coordinates<dim>& soil) {
    images_.clear();
    const double reach2 = reach_ * reach_;
    std::vector<std::size_t> near;
    std::vector<double> distance;
    for (const std::size_t j : soil_by_id(p)) {
      near.clear(), distance.clear();
      for (std::size_t k = 0; k < planes_.size(); ++k) {
        const SymmetryPlane& plane = planes_[k];
        const double d = std::max(plane.side * (soil[plane.axis][j] - plane.offset), 0.0);
        if (d <= reach_) near.push_back(k), distance.push_back(d);
      }
      for (unsigned set = 1; set < (1u << near.size()); ++set) {
        Image image{.source = j, .plane = planes_.size()};
        double d2 = 0.0;
        int axes = 0;
        bool distinct = true;
        for (std::size_t n = 0; n < near.size(); ++n) {
          if (!(set & (1u << n))) continue;
          const SymmetryPlane& plane = planes_[near[n]];
          distinct = distinct && !(axes & (1 << plane.axis));
          axes |= 1 << plane.axis;
          d2 += distance[n] * distance[n];
          image.sign[plane.axis] = -1.0;
          image.shift[plane.axis] = 2.0 * plane.offset;
          image.plane = std::min(image.plane, near[n]);
        }
        if (distinct && d2 <= reach2) images_.push_back(image);
      }
    }
    p.resize_boundary(p.image_begin - p.soil_count + images_.size());
    for (std::size_t k = 0; k < images_.size(); ++k) {
      set_wall_attributes(p, k);
      const std::size_t b = p.image_begin + k, j = images_[k].source;
      p.mass[b] = p.mass[j], p.density[b] = p.density[j];
    }
    place(p);
  }

  /// Gives every image its soil particle's reflected position and velocity (serial; at the close of
  /// each step, after the drift and the wall guard).
  void place(ParticlesOf<dim>& p) const {
    const auto x = positions(p);
    const auto v = p.velocity_arrays();
    for (std::size_t k = 0; k < images_.size(); ++k) {
      const Image& image = images_[k];
      const std::size_t b = p.image_begin + k;
      for (int a = 0; a < dim; ++a) {
        (*x[a])[b] = image.sign[a] * (*x[a])[image.source] + image.shift[a];
        (*v[a])[b] = image.sign[a] * (*v[a])[image.source];
      }
    }
  }

  /// Image b takes its soil particle's stress σ^n and density ρ^n, reflected (loop 1 of the step).
  void copy_stress(ParticlesOf<dim>& p, std::size_t b) const {
    const Image& image = images_[b - p.image_begin];
    const auto stress = stress_arrays(p);
    for (int a = 0; a < dim; ++a)
      for (int c = a; c < dim; ++c) {
        std::vector<double>& s = *stress[symmetric_index<dim>(a, c)];
        s[b] = image.sign[a] * image.sign[c] * s[image.source];
      }
    p.density[b] = p.density[image.source];
  }

  /// Image b takes its soil particle's velocity in v, reflected (loop 3 of the step).
  void copy_velocity(const ParticlesOf<dim>& p, std::size_t b, const MutableVelocitySpans<dim>& v) const {
    const Image& image = images_[b - p.image_begin];
    for (int a = 0; a < dim; ++a) v[a][b] = image.sign[a] * v[a][image.source];
  }

  /// The soil particle image b mirrors.
  std::size_t source(const ParticlesOf<dim>& p, std::size_t b) const { return images_[b - p.image_begin].source; }

 private:
  struct Image {
    std::size_t source;
    std::size_t plane;  ///< the first of its planes, whose wall it reports to
    std::array<double, dim> sign = filled<dim>(1.0), shift{};
  };

  template <int n>
  static constexpr std::array<double, n> filled(double v) {
    std::array<double, n> a{};
    a.fill(v);
    return a;
  }

  /// The soil's indices in order of their ids.
  static std::vector<std::size_t> soil_by_id(const ParticlesOf<dim>& p) {
    std::vector<std::size_t> order(p.soil_count);
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (!std::is_sorted(p.id.begin(), p.id.end()))
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
    return order;
  }

  static std::array<std::vector<double>*, dim> positions(ParticlesOf<dim>& p) {
    if constexpr (dim == 2)
      return {&p.x, &p.y};
    else
      return {&p.x, &p.y, &p.z};
  }

  /// Image k reports to its first plane's wall as a ghost of a free-slip wall at rest.
  void set_wall_attributes(ParticlesOf<dim>& p, std::size_t k) const {
    const Image& image = images_[k];
    const SymmetryPlane& plane = planes_[image.plane];
    const std::size_t g = p.image_begin - p.soil_count + k;
    std::array<double, 3> normal{};
    normal[static_cast<std::size_t>(plane.axis)] = plane.side;
    p.boundary_kind[g] = WallKind::FreeSlip;
    p.wall_nx[g] = normal[0], p.wall_ny[g] = normal[1];
    p.wall_vx[g] = p.wall_vy[g] = p.wall_friction[g] = p.wall_stick[g] = 0.0;
    p.wall_id[g] = plane.wall;
    if constexpr (dim == 3) {
      p.wall_nz[g] = normal[2], p.wall_vz[g] = 0.0;
      p.image_sign_x[g] = image.sign[0], p.image_sign_y[g] = image.sign[1], p.image_sign_z[g] = image.sign[2];
    }
  }

  std::vector<SymmetryPlane> planes_;
  double reach_ = 0.0;
  std::vector<Image> images_;
};

}  // namespace soilsph::sph
