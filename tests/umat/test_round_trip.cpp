// libsoilsph_umat.so loaded back through `model = "umat"`: on every shipped programme
// (data/programmes) it gives the built-in model's curve, to the driver's Newton tolerance (the only
// difference: the first Newton guess uses the UMAT's probe stiffness, not the model's elasticity).
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "constitutive/material.h"
#include "constitutive/material_description.h"
#include "verification/programme/programme_file.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {

/// The exported library's CMNAME and PROPS for a built-in model (docs/reference/umat-library.md).
std::string umat_keys(const Material& material) {
  return std::visit(
      [](const auto& m) -> std::string {
        using Model = std::decay_t<decltype(m)>;
        const auto& p = m.params();
        std::string props;
        const auto add = [&props](double x) { props += (props.empty() ? "" : ", ") + exact_number(x); };
        if constexpr (std::is_same_v<Model, ModifiedCamClay>) {
          add(p.poisson_ratio), add(p.friction_angle), add(p.compression_index), add(p.swelling_index);
          add(p.initial_void_ratio), add(p.elasticity == Elasticity::Kind::Constant ? p.young_modulus : 0.0);
          add(p.elastic_pressure_floor);
        } else if constexpr (std::is_same_v<Model, DruckerPrager> || std::is_same_v<Model, MohrCoulomb>) {
          add(p.young_modulus), add(p.poisson_ratio), add(p.friction_angle), add(p.cohesion),
              add(p.dilatancy_angle);
        } else {
          FAIL("no exported model for " << Model::kName);
        }
        if constexpr (requires { p.integrator; })
          return "name = \"" + std::string(Model::kName) + ":" + std::string(integrator_name(p.integrator)) +
                 "\"\nprops = [" + props + "]\n";
        return "";
      },
      material);
}

Material exported(const Material& builtin, double pc) {
  const std::string text = "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" +
                           std::string(SOILSPH_UMAT_LIBRARY) + "\"\n" + umat_keys(builtin) +
                           "state_variables = 4\ninitial_state = [" + exact_number(pc) + ", 0, 0, 0]\n";
  const toml::table root = toml::parse(text);
  return read_material(TableReader(*root["material"].as_table(), "round-trip.toml", "material"));
}

/// The largest difference of p, q, ε_v and ε_q over the rows, relative to each column's largest value
/// (for the strains at least the largest axial or shear strain: ε_v stays at round-off undrained).
double largest_relative_difference(const PointCurve& a, const PointCurve& b) {
  REQUIRE(a.size() == b.size());
  double strain_scale = 0.0;
  for (const PointRecord& r : b)
    strain_scale = std::max({strain_scale, std::abs(r.eps_a), std::abs(r.gamma_xy)});
  double worst = 0.0;
  for (auto column : {&PointRecord::p, &PointRecord::q, &PointRecord::eps_v, &PointRecord::eps_q}) {
    const bool strain = column == &PointRecord::eps_v || column == &PointRecord::eps_q;
    double scale = strain ? strain_scale : 0.0, difference = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      scale = std::max(scale, std::abs(b[k].*column));
      difference = std::max(difference, std::abs(a[k].*column - b[k].*column));
    }
    worst = std::max(worst, scale > 0.0 ? difference / scale : difference);
  }
  return worst;
}

}  // namespace

TEST_CASE("libsoilsph_umat reproduces the built-in models on every shipped programme", "[umat]") {
  int programmes = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(SOILSPH_SOURCE_DIR) + "/data/programmes")) {
    if (entry.path().extension() != ".toml") continue;
    const ProgrammeFile file = read_programme_file(entry.path().string());
    const std::string integrator = std::visit(
        [](const auto& m) -> std::string {
          if constexpr (requires { m.integrator(); }) return std::string(integrator_name(m.integrator()));
          return "implicit";
        },
        file.material);
    const PointCurve builtin = run_programme(file.material, file.programme, integrator);
    const PointCurve umat =
        run_programme(exported(file.material, file.programme.initial.pc), file.programme, integrator);
    CAPTURE(entry.path().filename().string(), integrator, umat[umat.size() / 2].q,
            builtin[builtin.size() / 2].q, umat.back().p, builtin.back().p, umat.back().eps_v,
            builtin.back().eps_v);
    CHECK(largest_relative_difference(umat, builtin) < 1e-9);
    ++programmes;
  }
  CHECK(programmes >= 6);
}
