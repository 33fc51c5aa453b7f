#pragma once
/// @file
/// Soil regions of space: each a solid (a box, a cylinder, an extruded polygon, a closed STL surface)
/// filled with the lattice nodes it contains, or particles imported as they are, and the material it
/// is made of (docs/reference/scenes.md, "Regions in 3D"). The 3D counterpart of the 2D layout's
/// regions (geometry/layout.h); the shorthands' soil is one such region.
#include <string>
#include <variant>
#include <vector>

#include "sph/geometry/cylinder.h"
#include "sph/geometry/extrusion.h"
#include "sph/geometry/solid.h"
#include "sph/geometry/stl.h"
#include "sph/geometry/vec3.h"

namespace soilsph::sph {

/// Particles imported from a file (geometry/read_particles_3d.h), at their own positions, which need
/// not lie on the lattice.
struct ParticleCloud3 {
  std::vector<Vec3> positions;  ///< m, in file order
  Box3 cells;                   ///< the box of the particles' cells (each Δp wide around its centre)
};

/// An axis-aligned box of soil, a SolidShape (geometry/solid.h): its sides lie on cell edges of the
/// lattice (sph/read_regions_3d.h), so no node lies on one and no tolerance is needed.
struct SoilBox {
  Box3 box;
  bool contains(Vec3 p) const { return box.contains(p); }
  Box3 bounds() const { return box; }
};

/// What a region is: a solid filled with lattice nodes, or a particle cloud taken as it is.
using RegionShape3 = std::variant<SoilBox, ColumnCylinder, Extrusion, StlSolid, ParticleCloud3>;

struct SoilRegion3 {
  RegionShape3 shape;
  std::string material;  ///< the name of its [materials.NAME] table ("" for [material])
  std::string name;      ///< for messages, e.g. "[regions #2]"
};

/// The box that holds a region (a cloud: its particles' cells).
Box3 region_bounds(const SoilRegion3& region);

/// About how many particles a region holds at `spacing`, without building them: its volume in cells
/// (a cylinder's part, an extrusion's area times its length, an STL solid's enclosed volume), a
/// cloud's count. For estimates (sph/feasibility.h).
double estimated_particles(const SoilRegion3& region, double spacing);

struct SoilNode3 {
  Vec3 position;
  int region;  ///< index into the regions
};

/// The soil of the regions, region by region: a solid's lattice nodes in the order of
/// lattice_nodes_inside (k, then j, then i), a cloud's particles in file order. With several regions
/// a lattice node that an earlier region holds is not repeated (the first region listed wins, as in
/// 2D; clouds are taken whole, as in 2D). Throws ParameterError naming `source`, the region and the
/// spacing for a region that holds no node.
std::vector<SoilNode3> soil_nodes_3d(const std::vector<SoilRegion3>& regions, const Lattice3& lattice,
                                     const std::string& source);

}  // namespace soilsph::sph
