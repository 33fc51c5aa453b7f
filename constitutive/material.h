#pragma once
/// @file
/// The one factory from input to model: a `[material]` TOML table becomes one of the model types.
/// Callers choose the model once (std::visit) and run code instantiated for it, so the per-particle
/// update is a direct, inlinable call.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "constitutive/model_concept.h"
#include "constitutive/models/drucker_prager.h"
#include "constitutive/models/linear_elastic.h"
#include "constitutive/models/modified_cam_clay.h"
#include "constitutive/models/mohr_coulomb.h"
#include "constitutive/models/umat.h"

namespace soilsph {

using Material = std::variant<LinearElastic, DruckerPrager, ModifiedCamClay, MohrCoulomb, UmatModel>;
static_assert(ConstitutiveModel<LinearElastic> && ConstitutiveModel<UmatModel>);
static_assert(PlasticModel<DruckerPrager> && PlasticModel<ModifiedCamClay> && PlasticModel<MohrCoulomb>);

/// Every key a `[material]` table may hold, whichever model it selects: `model`, then the keys of each
/// model's Params (its fields() list) not listed before, in the order of
/// the models in Material.
std::span<const std::string_view> material_keys();

/// Builds the model that `table` selects with its `model` key, validating every parameter. Keys of
/// other models are reported on stderr as ignored; keys no model knows are errors.
Material read_material(const TableReader& table);
/// The dotted name of the table that holds a file's material: "material", or "materials.NAME" for a
/// scene's named material `name` (`--material NAME`).
std::string material_table_name(std::string_view name);
/// The table `material_table_name(name)` of `root`, read from `path`. Without it, a ParameterError
/// naming the file and, for a scene of named materials, the names it holds and `--material NAME`,
/// the option that picks one.
const toml::table& material_table(const toml::table& root, const std::string& path, std::string_view name);
/// Reads the `[material]` table of a TOML file (a material file or a scene file), or a scene's
/// `[materials.NAME]` for `name`.
Material load_material(const std::string& path, std::string_view name = "");

/// A copy of `material` that integrates its stress with `integrator` (models without a plastic
/// update, i.e. linear elasticity, are returned unchanged).
Material with_integrator(const Material& material, Integrator integrator);

/// A copy of `material` rebuilt from its parameters after `edit(params)` (called with the chosen
/// model's Params; use `if constexpr (requires { params.field; })` for fields some models lack).
template <class Edit>
Material with_edited_params(const Material& material, Edit edit) {
  return std::visit(
      [&edit](const auto& model) -> Material {
        using Model = std::decay_t<decltype(model)>;
        typename Model::Params params = model.params();
        edit(params);
        return Model(params);
      },
      material);
}

std::string_view model_name(const Material& material);
double density(const Material& material);
/// The Duvaut–Lions relaxation time τ of the SPH solver (s; constitutive/viscoplastic_relaxation.h):
/// 0 for a rate-independent material and for linear elasticity.
double viscoplastic_relaxation_time(const Material& material);

/// Whether the model exposes its rate equations, which the CVODE reference integrates: every built-in
/// model does; a UMAT plug-in offers only its incremental update (its work–precision reference is its
/// own solution at a fine increment).
bool has_rate_form(const Material& material);

/// Whether the model has a preconsolidation pressure, i.e. whether an OCR applies to it.
bool has_preconsolidation(const Material& material);
/// The names of the models that have one, for messages: "modified-cam-clay".
std::string preconsolidation_models();
/// The model's initial hardening state at effective stress `sigma` (tension-positive) with
/// overconsolidation ratio `ocr` (its initial_preconsolidation hook; 0 for models without one).
double initial_preconsolidation(const Material& material, const Mat3& sigma, double ocr);
/// The model's failure (critical-state) line on the triaxial-compression meridian; none for
/// linear elasticity.
std::optional<FailureLine> triaxial_failure_line(const Material& material);

}  // namespace soilsph
