#pragma once
/// @file
/// A read-only view of the soil particles at one instant: what the solver hands to the writers.
///
/// Conventions (see docs/reference/output-formats.md): SI units; y vertical (up), x horizontal and,
/// in 3D, z the other horizontal axis (2D is plane strain in x, y); stress components
/// tension-positive as inside the solver (paper eq 9–10); p and q compression-positive
/// soil-mechanics invariants (constitutive/tensor.h).
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace soilsph::sph {

/// The selectable output fields of a frame (`[output] fields` in a scene). Each name is the HDF5
/// dataset (and XDMF attribute) it writes, except `stress`, which writes the components together:
/// sxx, syy, szz, sxy in 2D, and sxz, syz too in 3D. The positions are always written (they are the XDMF geometry).
enum class Field : std::uint8_t { velocity, speed, stress, p, q, plastic_strain, density, layer, material };

/// The field names in the order of enum Field (and of the datasets in a frame).
inline constexpr std::array<std::string_view, 9> kFieldNames{"velocity", "speed",   "stress", "p",       "q",
                                                             "plastic_strain", "density", "layer", "material"};

/// The Field called `name`, or none if no field has that name.
constexpr std::optional<Field> field_named(std::string_view name) {
  for (std::size_t i = 0; i < kFieldNames.size(); ++i) {
    if (kFieldNames[i] == name) return static_cast<Field>(i);
  }
  return std::nullopt;
}

/// A set of fields; default-constructed it is empty, FieldSet::all() holds every field.
class FieldSet {
 public:
  static constexpr FieldSet all() {
    FieldSet s;
    s.bits_ = static_cast<std::uint32_t>((1u << kFieldNames.size()) - 1u);
    return s;
  }
  constexpr FieldSet& insert(Field f) {
    bits_ |= bit(f);
    return *this;
  }
  constexpr bool contains(Field f) const { return (bits_ & bit(f)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr bool operator==(const FieldSet&) const = default;

 private:
  static constexpr std::uint32_t bit(Field f) { return 1u << static_cast<unsigned>(f); }
  std::uint32_t bits_ = 0;
};

/// A read-only view of the soil particles at one instant (boundary particles excluded unless noted).
/// Every span has one entry per particle and they all have the same length; a writer that writes
/// only some fields (FieldSet) ignores the spans of the others, which may then be empty.
struct Frame {
  double time = 0.0;                           ///< s
  std::span<const double> x, y, vx, vy;        ///< m, m/s
  std::span<const double> sxx, syy, szz, sxy;  ///< Pa, tension-positive stress components
  std::span<const double> p, q;                ///< Pa, compression-positive p, von Mises q
  std::span<const double> plastic_strain;      ///< accumulated equivalent plastic strain
  std::span<const double> density;             ///< kg/m^3
  std::span<const int> layer;                  ///< horizontal layer id (0,1,2,... from the bottom)
  std::span<const int> material;               ///< index of the particle's material (summary.json "materials")
  std::span<const std::uint64_t> id{};         ///< the particles' global ids (ParticlesOf::id); written if given
  int dimension = 2;                           ///< 2: positions (x, y, 0); 3: (x, y, z) and the spans below
  std::span<const double> z{}, vz{};           ///< 3D only: m, m/s
  std::span<const double> sxz{}, syz{};        ///< 3D only: Pa, tension-positive
  /// UMAT plug-ins' STATEV ([output] state_variables): variable k (from 0) of particle i at k n + i,
  /// written as statev_1 … statev_K; zeros for a particle of a built-in model. Empty: none.
  std::span<const double> state_variables{};
  int state_variable_count = 0;  ///< K
};

}  // namespace soilsph::sph
