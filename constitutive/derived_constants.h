#pragma once
/// @file
/// The constants a model derives from its keys (moduli, α_φ, k_c, M, the hardening exponent) must be
/// finite and positive: in-range keys can still combine into an overflow (e0 = 1e308 makes
/// (1+e0)/(λ−κ) infinite) or an underflow (E = 5e-324 makes G = 0), which would turn every stress
/// into inf or NaN. Checked when a material is read; the error names the key and the bound.
#include "constitutive/material.h"

namespace soilsph {

/// Throws ParameterError (through `table`, so it names the file or --set option and the key) for
/// the first derived constant of `material` that is not finite and positive.
void check_derived_constants(const Material& material, const TableReader& table);

}  // namespace soilsph
