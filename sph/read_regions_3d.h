#pragma once
/// @file
/// The geometry of a 3D scene built from [[regions]] (docs/reference/scenes.md, "Regions in 3D"):
/// the soil regions on the lattice, the materials they name, the levels the initial state and the
/// rest criterion take, the floor the soil stands on, and the frame of the deposit measures
/// ([deposit] axis). Every key validated, each error naming the file, the table and the key.
#include <toml++/toml.h>
#include <string>
#include <vector>

#include "constitutive/parameters.h"
#include "sph/scene_3d.h"

namespace soilsph::sph {

/// The regions of `root`'s [[regions]] on `lattice`; a region's `material` must be one of
/// `materials` (its default: the only one). `resolved` gets each table as read, defaults included.
std::vector<SoilRegion3> read_regions_3d(const toml::table& root, const std::string& source,
                                         const Lattice3& lattice, const std::vector<std::string>& materials,
                                         toml::array& resolved);

/// A regions scene's [scene] keys (particle_spacing, smoothing_ratio, end_time, boundary_layers,
/// lattice_origin, floor_level, floor_margin) and its [[regions]], into `g` (whose gravity is read):
/// the regions, the lattice, the levels, the floor and the domain. `extra` gets the [scene] keys read
/// without `t` (lattice_origin), `regions` the [[regions]] as read.
void read_regions_geometry(const TableReader& t, const toml::table& table, const toml::table& root,
                           Geometry3& g, const std::vector<std::string>& materials, toml::table& extra,
                           toml::array& regions);

/// The walls of a regions scene: a no-slip floor, the plane y = floor_level under the soil's x–z
/// extent widened by `margin` on every side; and the domain around it (domain_around).
void add_regions_floor(Geometry3& g, double margin, const std::string& source);

/// The materials the regions use, as indices into `names`, in the order of their first use; each
/// region's index into that list in `region_material`.
std::vector<std::size_t> materials_in_use(const std::vector<SoilRegion3>& regions,
                                          const std::vector<std::string>& names,
                                          std::vector<int>& region_material);

/// [deposit] of a regions scene: `axis = [x, z]`, the vertical axis the axisymmetric measures take
/// (analysis/axisymmetric_deposit.h), standing on the floor; `azimuth_span` (degrees, default 360),
/// the azimuths from +x towards +z that the soil covers. Without the table the deposit is not
/// measured (Geometry3::deposit_measured false). `resolved` gets the table as read.
void read_deposit_3d(const toml::table& root, const std::string& source, Geometry3& g, toml::table& resolved);

}  // namespace soilsph::sph
