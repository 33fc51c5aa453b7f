#pragma once
/// @file
/// Reads what a scene measures (docs/reference/scenes.md): [deposit], the frame of the deposit measures, and
/// [[gauges]], the points sampled over time; every key validated, each error naming the file, the
/// table and the key.
#include <string>
#include <toml++/toml.h>
#include <vector>

#include "constitutive/parameters.h"
#include "sph/analysis/deposit.h"
#include "sph/analysis/gauges.h"

namespace soilsph::sph {

struct Geometry;

/// [deposit] origin, direction, toe_thickness; the defaults are the column's measures: from
/// (the soil's largest x, 0), the column's fixed wall, along −x (in general across gravity, a
/// quarter turn clockwise from it), toe thickness a tenth of the soil's height (both
/// Geometry::soil_extent). A scene of [[regions]] measures its deposit only if the table is `given`
/// (an empty one takes the defaults, the soil's largest x as the wall): else the frame is undefined
/// (DepositFrame::defined). `resolved` gets the table as read, defaults included.
DepositFrame read_deposit(const TableReader& t, const toml::table& table, bool given, const Geometry& g,
                          toml::table& resolved);

/// [[gauges]] name, position ([x, y], in space [x, y, z]), kind; `resolved` gets each as read, defaults included.
template <int dim = 2>
std::vector<GaugeOf<dim>> read_gauges(const toml::table& root, const std::string& source, toml::array& resolved);

}  // namespace soilsph::sph
