#pragma once
/// @file
/// Programme files (`soilsph point PROGRAMME.toml`, docs/reference/programmes.md): a laboratory programme
/// written down. Inputs are compression-positive (stresses Pa, strains 1; shears as τ and γ = 2ε
/// of the compression-positive tensors); x is the axial (vertical) direction.
///
///   material = "mcc.toml"            # a material file (relative to this file), or a [material] table
///   [initial]                        # p = P (isotropic), or vertical_stress = S with an optional
///   p = 100e3                        # lateral_stress_ratio (K0); ocr (MCC, default 1)
///   [[leg]]                          # as many as needed, run in order
///   drainage = "undrained"           # or "drained" (default)
///   increments = 100                 # per target (default 100)
///   strain = { xx = 0.1 }            # targets at the leg's end; a list: targets in turn
///   stress = { yy = "hold", zz = "hold" }   # a number, "hold", or a list of them
///   repeat = 1                       # the list of targets traversed this many times (cyclic legs)
///
/// Components named in neither table keep their strain. Every value is validated with the file,
/// the key and the allowed range in the message (ParameterError).
#include <span>
#include <string>
#include <vector>

#include "constitutive/material.h"
#include "verification/programme/programme.h"

namespace soilsph::verification {

struct ProgrammeFile {
  Material material;
  std::string material_source;  ///< the material file, or the programme file for an inline table
  Programme programme;
  /// One line for a CSV's provenance: the file, the initial state as resolved, the legs.
  std::string description;
};

/// True when the TOML file at `path` holds `[[leg]]` tables (a programme, not a material file).
bool is_programme_file(const std::string& path);

/// Reads a programme; `overrides` are `--set material.KEY=VALUE` applied to its material.
ProgrammeFile read_programme_file(const std::string& path, std::span<const std::string> overrides = {});
/// read_programme_file() of a file already parsed into `root` (a caller that runs one programme with
/// many materials replaces its `material` and reads it again without parsing the file each time).
ProgrammeFile read_programme(const toml::table& root, const std::string& path,
                             std::span<const std::string> overrides = {});

}  // namespace soilsph::verification
