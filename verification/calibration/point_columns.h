#pragma once
/// @file
/// The columns of a point curve (verification/point_test.h, PointRecord) by name, with their kind, so
/// measured CSVs and the driver's curves are compared column by column and units are converted once.
#include <optional>
#include <string>
#include <string_view>

#include "verification/point_test.h"

namespace soilsph::calibration {

enum class Quantity { Strain, Stress };

struct PointColumn {
  std::string_view name;
  double verification::PointRecord::*field;
  Quantity quantity;
};

/// In the order of the point CSV's columns.
inline constexpr PointColumn kPointColumns[] = {
    {"eps_a", &verification::PointRecord::eps_a, Quantity::Strain},
    {"eps_r", &verification::PointRecord::eps_r, Quantity::Strain},
    {"eps_v", &verification::PointRecord::eps_v, Quantity::Strain},
    {"eps_q", &verification::PointRecord::eps_q, Quantity::Strain},
    {"sig_a", &verification::PointRecord::sig_a, Quantity::Stress},
    {"sig_r", &verification::PointRecord::sig_r, Quantity::Stress},
    {"p", &verification::PointRecord::p, Quantity::Stress},
    {"q", &verification::PointRecord::q, Quantity::Stress},
    {"p_c", &verification::PointRecord::p_c, Quantity::Stress},
    {"u", &verification::PointRecord::u, Quantity::Stress},
    {"tau_xy", &verification::PointRecord::tau_xy, Quantity::Stress},
    {"gamma_xy", &verification::PointRecord::gamma_xy, Quantity::Strain},
};

/// The column called `name`, if the driver produces one.
inline std::optional<PointColumn> point_column(std::string_view name) {
  for (const PointColumn& column : kPointColumns)
    if (column.name == name) return column;
  return std::nullopt;
}

/// "eps_a, eps_r, ...": for messages.
inline std::string point_column_names() {
  std::string list;
  for (const PointColumn& column : kPointColumns) list.append(list.empty() ? "" : ", ").append(column.name);
  return list;
}

}  // namespace soilsph::calibration
