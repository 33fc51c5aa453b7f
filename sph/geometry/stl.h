#pragma once
/// @file
/// Soil shapes from STL files (ASCII or binary): a closed triangulated surface and which points it
/// encloses (docs/method/geometry-3d.md, "STL solids").
#include <cstddef>
#include <string>
#include <vector>

#include "sph/geometry/vec3.h"

namespace soilsph::sph {

struct Triangle {
  Vec3 a, b, c;
};

/// The facets of an STL file in file order, ASCII (`solid … endsolid`) or binary (80-byte header,
/// facet count, 50 bytes a facet), told apart by the binary layout's exact size. Coordinates are
/// taken as metres times `scale`. Throws ParameterError naming the file, and the line and facet
/// where it applies: an unreadable file, a size that fits neither form, a malformed line, a number
/// that does not parse or is not finite, no facet.
std::vector<Triangle> read_stl(const std::string& path, double scale = 1.0);

/// A closed surface and its inside test. The test casts a ray from the point along +z and counts
/// the facets it crosses (even-odd); a ray through an edge or a vertex of the facets' projections
/// on the x–y plane is decided by one fixed tie rule (a point on an edge counts for the facet on
/// the edge's left when the edge points up, or left when it is horizontal: a symbolic shift of the
/// point by (−ε, −ε²)), computed in one canonical order per edge so that two facets sharing an edge
/// see the same sign; the ray through a shared edge or vertex thus crosses exactly one facet, or
/// two (a silhouette it grazes), never a wrong count. A point within 10⁻⁹ of the extent of a facet
/// the ray crosses counts as inside. Facets are binned on an x–y grid so a test costs the facets
/// over its bin only.
class StlSolid {
 public:
  /// Validates the surface, naming `source` and the facet (1-based, file order): fewer than 4
  /// facets, a facet of zero area, or an edge not shared by exactly two facets (not closed).
  StlSolid(std::vector<Triangle> triangles, const std::string& source);

  bool contains(Vec3 p) const;
  Box3 bounds() const { return bounds_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// The enclosed volume by the divergence theorem, Σ a·(b × c)/6 (the facets consistently
  /// oriented; the absolute value, so either orientation).
  double volume() const;

 private:
  std::vector<Triangle> triangles_;
  Box3 bounds_;
  double tolerance_;                     ///< 10⁻⁹ of the extent
  std::size_t bins_x_ = 1, bins_y_ = 1;  ///< the x–y grid over bounds_
  double bin_dx_ = 1.0, bin_dy_ = 1.0;
  std::vector<std::vector<std::size_t>> bin_;  ///< facets whose x–y box meets each bin, bin_x + bins_x_·bin_y
  std::size_t bin_of(double x, double y) const;
};

/// read_stl then StlSolid: the soil shape of an STL file.
StlSolid load_stl_solid(const std::string& path, double scale = 1.0);

}  // namespace soilsph::sph
