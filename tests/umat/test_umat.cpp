// UMAT plug-ins written in this project, loaded through `model = "umat"` and run by the point
// driver, against soilsph's closed forms; and the adapter's answers to faulty plug-ins.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/temp_dir.h"
#include "constitutive/material.h"
#include "constitutive/material_description.h"
#include "constitutive/stress_test.h"
#include "constitutive/tangent.h"
#include "tests/common/table1_materials.h"
#include "verification/closed_form/closed_form.h"
#include "verification/report/case_result.h"
#include "verification/report/curve_errors.h"
#include "verification/report/verification_case.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {

/// A [material] table naming `library` (absolute) with the given extra lines.
Material umat_material(const std::string& library, const std::string& lines) {
  const std::string text =
      "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" + library + "\"\n" + lines;
  const toml::table root = toml::parse(text);
  return read_material(TableReader(*root["material"].as_table(), "test.toml", "material"));
}

CurveErrors against_closed_form(const Material& umat, const Material& builtin, const PointTest& test,
                                const std::string& closed_form) {
  const PointCurve curve = run_point_test(umat, test, "implicit");
  std::vector<double> driven;
  for (const PointRecord& row : curve) driven.push_back(driven_strain(row, test.path));
  return curve_errors(curve, closed_form_curve(closed_form, builtin, test, driven), test.path);
}

const std::string kElasticC = std::string(SOILSPH_UMAT_MISBEHAVING_C);

using soilsph::testing::TempDir;

}  // namespace

TEST_CASE("A C UMAT with a renamed entry point follows Hooke's law on a drained triaxial path", "[umat]") {
  const Material umat =
      umat_material(kElasticC, "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\n");
  // The probe call's DDSDDE gives back E and ν.
  const Moduli D = std::get<UmatModel>(umat).elasticity().at(0.0);
  CHECK(D.K == Approx(1e6 / (3.0 * 0.4)).epsilon(1e-14));
  CHECK(D.G == Approx(1e6 / 2.6).epsilon(1e-14));
  PointTest test;
  test.strain_targets = {0.01};
  test.increments = 10;
  const PointCurve curve = run_point_test(umat, test, "implicit");
  // Elastic drained triaxial: q = E ε_a, ε_v = (1 − 2ν) ε_a.
  CHECK(curve.back().q == Approx(1e6 * 0.01).epsilon(1e-10));
  CHECK(curve.back().eps_v == Approx(0.4 * 0.01).epsilon(1e-10));
}

#ifdef SOILSPH_UMAT_LINEAR_ELASTIC_F
TEST_CASE("A Fortran linear-elastic UMAT in kPa reproduces the elastic closed forms", "[umat]") {
  // E = 1000 kPa = 1 MPa: the adapter scales stresses and DDSDDE.
  const Material umat = umat_material(SOILSPH_UMAT_LINEAR_ELASTIC_F,
                                      "props = [1000.0, 0.3]\nstress_unit = \"kPa\"\nname = \"ELASTIC\"\n");
  // The D-P cone is not reached before ε_a ≈ 0.14 (E = 1 MPa, p = 100 kPa): its closed forms' elastic
  // branches apply to the elastic UMAT.
  const Material builtin = test::table1_drucker_prager();
  PointTest test;
  test.strain_targets = {0.05};
  test.increments = 20;
  for (const auto& [path, name] :
       {std::pair{LoadPath::TriaxialDrained, "dp-triaxial-drained"},
        std::pair{LoadPath::Oedometer, "dp-oedometer"}, std::pair{LoadPath::Isotropic, "dp-isotropic"}}) {
    test.path = path;
    CAPTURE(name);
    CHECK(against_closed_form(umat, builtin, test, name).max() < 1e-12);
  }
}
#endif

#ifdef SOILSPH_UMAT_DRUCKER_PRAGER_F
TEST_CASE("A Fortran Drucker-Prager UMAT reproduces the D-P closed forms through yield", "[umat]") {
  for (const double dilatancy : {0.0, 5.0}) {
    CAPTURE(dilatancy);
    const Material umat = umat_material(
        SOILSPH_UMAT_DRUCKER_PRAGER_F,
        "props = [1.0e6, 0.3, 35.0, 5000.0, " + std::to_string(dilatancy) + "]\nstate_variables = 1\n");
    const Material builtin = test::table1_drucker_prager(5e3, dilatancy);
    PointTest test;
    test.strain_targets = {0.3};
    test.path = LoadPath::TriaxialDrained;
    CHECK(against_closed_form(umat, builtin, test, "dp-triaxial-drained").max() < 1e-10);
    test.path = LoadPath::TriaxialUndrained;
    test.strain_targets = {0.2};
    CHECK(against_closed_form(umat, builtin, test, "dp-triaxial-undrained").max() < 1e-8);
  }
}

TEST_CASE("The Fortran Drucker-Prager UMAT's DDSDDE is the derivative of its stress update", "[umat]") {
  const UmatModel umat = std::get<UmatModel>(umat_material(
      SOILSPH_UMAT_DRUCKER_PRAGER_F, "props = [1.0e6, 0.3, 35.0, 5000.0, 5.0]\nstate_variables = 1\n"));
  State state;
  state.stress = -1e5 * Mat3::Identity();
  Mat3 increment = Mat3::Zero();
  increment(0, 0) = -0.5, increment(1, 1) = 0.2,
               increment(0, 1) = increment(1, 0) = 0.03;  // far past the cone
  const Mat6 returned = umat.returned_tangent(state, increment);
  const Mat6 differences = finite_difference_tangent(umat, state, increment);
  CHECK((returned - differences).norm() < 1e-6 * differences.norm());
  CHECK((returned - voigt_isotropic_stiffness(umat.elasticity().at(0).K, umat.elasticity().at(0).G)).norm() >
        1e-2 * differences.norm());  // plastic: not the elastic stiffness
}
#endif

TEST_CASE("PNEWDT < 1 halves the increment: a linear UMAT gives the same stress", "[umat]") {
  const Material halves =
      umat_material(kElasticC, "symbol = \"umat_elastic_c\"\nname = \"HALVES\"\nprops = [1.0e6, 0.3]\n");
  Mat3 increment = Mat3::Zero();
  increment(0, 0) = -1e-3;  // ten times the size it accepts: cut in 16 pieces
  const State next = std::get<UmatModel>(halves).update(State{}, increment, Mat3::Zero());
  CHECK(next.stress(0, 0) == Approx(-1e6 * 0.7 / (1.3 * 0.4) * 1e-3).epsilon(1e-13));
  CHECK(next.umat.increment == 16);
  CHECK(next.umat.strain[0] == Approx(-1e-3).epsilon(1e-15));
}

TEST_CASE("A faulty UMAT gets one error naming the library, the symbol and the call", "[umat]") {
  const auto fails_with = [](const std::string& name, const std::string& what) {
    const Material bad = umat_material(
        kElasticC, "symbol = \"umat_elastic_c\"\nname = \"" + name + "\"\nprops = [1.0e6, 0.3]\n");
    PointTest test;
    test.strain_targets = {0.01};
    test.increments = 4;
    CAPTURE(name);
    CHECK_THROWS_WITH(run_point_test(bad, test, "implicit"),
                      Catch::Contains(kElasticC) && Catch::Contains("umat_elastic_c") &&
                          Catch::Contains("KINC = ") && Catch::Contains(what));
  };
  fails_with("PNEWDT", "asked for a smaller increment (PNEWDT = 0.5) after 10 halvings");
  fails_with("NAN-STRESS", "non-finite STRESS");
}

TEST_CASE("A zero DDSDDE falls back to central differences, counted", "[umat]") {
  const UmatModel umat = std::get<UmatModel>(umat_material(
      kElasticC, "symbol = \"umat_elastic_c\"\nname = \"ZERO-TANGENT\"\nprops = [1.0e6, 0.3]\n"));
  const long before = umat.fallback_count();
  Mat3 increment = Mat3::Zero();
  increment(0, 0) = -1e-3;
  const Mat6 tangent = umat.consistent_tangent(State{}, increment);
  CHECK((tangent - voigt_isotropic_stiffness(1e6 / 1.2, 1e6 / 2.6)).norm() < 1e-6 * tangent.norm());
  CHECK(umat.fallback_count() == before + 1);
}

TEST_CASE("Bad UMAT tables are refused when read, naming the key", "[umat]") {
  const auto refused = [](const std::string& lines, const std::string& what) {
    CAPTURE(lines);
    CHECK_THROWS_WITH(umat_material(kElasticC, lines), Catch::Contains(what));
  };
  refused("symbol = \"umat_missing_\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\n",
          "symbol = \"umat_missing_\" is not exported");
  refused("symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3, 7.0]\n",
          "props has 3 values; " + kElasticC + " expects 2");
  refused("symbol = \"umat_elastic_c\"\nname = \"UNKNOWN\"\nprops = [1.0e6, 0.3]\n", "is not a material");
  refused("symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, \"x\"]\n",
          "props: element 2 must be a number");
  refused(
      "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\nstate_variables = "
      "2\ninitial_state = [1.0]\n",
      "test.toml: [material] initial_state: has 1 values (allowed: 0 or 2 values, as state_variables = 2)");
  refused("symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\nstress_unit = \"GPa\"\n",
          "test.toml: [material] stress_unit = \"GPa\" is not allowed (allowed: \"Pa\", \"kPa\", \"MPa\")");
  refused("symbol = \"\"\n",
          "test.toml: [material] symbol = \"\" has 0 characters (allowed: at least 1 character)");
  refused("symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\nthread_safe = \"yes\"\n",
          "test.toml: [material] thread_safe: must be true or false");
  refused("symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\nstate_variables = 100000\n",
          "state_variables");
  CHECK_THROWS_WITH(umat_material("/nonexistent/libnothing.so", "props = []\n"),
                    Catch::Contains("is not a file"));
}

TEST_CASE("A UMAT material is described with every key it was given, in its fields() order", "[umat]") {
  // Every key set off its default; the description is the TOML that reads the material back.
  const std::string lines =
      "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1000000, 0.3]\nstate_variables = 2\n"
      "initial_state = [0.5, 2]\nstress_unit = \"kPa\"\nthread_safe = true\n";
  const Material umat = umat_material(kElasticC, lines);
  CHECK(describe_material(umat) ==
        "model = \"umat\"; density = 2000; library = \"" + kElasticC +
            "\"; symbol = \"umat_elastic_c\"; name = \"ELASTIC\"; props = [1000000, 0.3]; "
            "state_variables = 2; initial_state = [0.5, 2]; stress_unit = \"kPa\"; "
            "thread_safe = true");
  // The keys a [material] table may hold are those of the list, whichever model it selects.
  const std::vector<std::string_view> keys = field_keys<UmatParams>();
  CHECK(keys == std::vector<std::string_view>{"density", "library", "symbol", "name", "props",
                                              "state_variables", "initial_state", "stress_unit",
                                              "thread_safe"});
  for (const std::string_view key : keys)
    CHECK(std::find(material_keys().begin(), material_keys().end(), key) != material_keys().end());
  // Without initial_state (the default, zeros) the description leaves it out.
  CHECK_THAT(
      describe_material(umat_material(kElasticC,
                                      "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\n"
                                      "props = [1000000, 0.3]\n")),
      !Catch::Contains("initial_state") && Catch::Contains("state_variables = 0; stress_unit = \"Pa\"; "
                                                           "thread_safe = false"));
  // The struct built in code is checked by the same list.
  UmatParams params = std::get<UmatModel>(umat).params();
  params.name = std::string(81, 'x');
  CHECK_THROWS_WITH(UmatModel(params),
                    Catch::Contains("umat parameters: name = \"" + std::string(81, 'x') +
                                    "\" has 81 characters (allowed: at most 80 characters)"));
}

TEST_CASE("A relative library path is relative to the TOML file", "[umat]") {
  const TempDir temp("soilsph-umat");
  const auto& dir = temp.path();
  std::filesystem::create_directories(dir / "lib");
  std::filesystem::copy_file(kElasticC, dir / "lib" / "elastic.so",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "material.toml")
      << "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"lib/elastic.so\"\n"
         "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\n";
  const Material m = load_material((dir / "material.toml").string());
  CHECK(std::get<UmatModel>(m).params().library ==
        std::filesystem::absolute(dir / "lib" / "elastic.so").lexically_normal().string());
}

TEST_CASE("A UMAT that crashes or aborts inside a call gets an error naming the call, and soilsph goes on",
          "[umat]") {
  for (const auto& [name, signal] : {std::pair{"SEGFAULT", "SIGSEGV"}, std::pair{"ABORT", "SIGABRT"}}) {
    CAPTURE(name);
    const Material bad = umat_material(kElasticC, "symbol = \"umat_elastic_c\"\nname = \"" +
                                                      std::string(name) + "\"\nprops = [1.0e6, 0.3]\n");
    PointTest test;
    test.strain_targets = {0.01};
    test.increments = 4;
    CHECK_THROWS_WITH(run_point_test(bad, test, "implicit"),
                      Catch::Contains(kElasticC) && Catch::Contains("umat_elastic_c") &&
                          Catch::Contains("KINC = 1, NOEL = 1") &&
                          Catch::Contains(std::string("crashed with ") + signal));
  }
  // The process is whole: the same library's sound entry still runs (q = E ε_a, drained triaxial).
  const Material elastic =
      umat_material(kElasticC, "symbol = \"umat_elastic_c\"\nname = \"ELASTIC\"\nprops = [1.0e6, 0.3]\n");
  PointTest test;
  test.strain_targets = {0.01};
  test.increments = 4;
  CHECK(run_point_test(elastic, test, "implicit").back().q == Approx(1e4).epsilon(1e-10));
}

#ifdef SOILSPH_UMAT_DRUCKER_PRAGER_F
TEST_CASE("verify runs a case of a UMAT against the closed form of the model it claims to be", "[umat]") {
  const TempDir temp("soilsph-umat");
  std::ofstream(temp.path() / "dp-umat.toml")
      << "[material]\nmodel = \"umat\"\ndensity = 2000.0\nlibrary = \"" << SOILSPH_UMAT_DRUCKER_PRAGER_F
      << "\"\nprops = [1.0e6, 0.3, 35.0, 0.0, 0.0]\nstate_variables = 1\n";
  // Table 1's D-P (φ = 35°), and the same soil with φ = 30°: a closed form the UMAT does not follow.
  std::ofstream(temp.path() / "dp-30.toml")
      << "[material]\nmodel = \"drucker-prager\"\ndensity = 2000.0\n"
         "young_modulus = 1.0e6\npoisson_ratio = 0.3\nfriction_angle = 30.0\n";
  const std::string table1 = std::string(SOILSPH_SOURCE_DIR) + "/data/materials/dp-table1.toml";
  const auto case_text = [](const std::string& name, const std::string& path, const std::string& closed_form,
                            const std::string& against) {
    return "[[case]]\nname = \"" + name + "\"\nmaterial = \"dp-umat.toml\"\npath = \"" + path +
           "\"\nstrain_targets = [0.3]\nclosed_form = \"" + closed_form + "\"\nclosed_form_material = \"" +
           against + "\"\ntolerance = { umat = 1e-8 }\n";
  };
  std::ofstream(temp.path() / "cases.toml")
      << case_text("umat-drained", "triaxial-drained", "dp-triaxial-drained", table1)
      << case_text("umat-undrained", "triaxial-undrained", "dp-triaxial-undrained", table1)
      << case_text("umat-against-phi-30", "triaxial-drained", "dp-triaxial-drained", "dp-30.toml");
  const auto cases = verification::read_cases(temp.path() / "cases.toml");
  REQUIRE(cases.size() == 3);
  for (const auto& c : cases) {
    const verification::CaseResult result = verification::run_case(c);
    CAPTURE(c.name);
    REQUIRE(result.runs.size() == 1);
    CHECK(result.runs[0].integrator == "umat");
    CHECK(result.runs[0].passed == (c.name != "umat-against-phi-30"));
  }
  // A UMAT case takes no CVODE or integrator tolerance; a built-in case no umat one.
  std::ofstream(temp.path() / "bad.toml")
      << "[[case]]\nname = \"bad\"\nmaterial = \"dp-umat.toml\"\npath = "
         "\"triaxial-drained\"\nstrain_targets = [0.3]\ntolerance = { cvode = 1e-5 }\n";
  CHECK_THROWS_WITH(verification::read_cases(temp.path() / "bad.toml"),
                    Catch::Contains("cvode") && Catch::Contains("does not apply to a umat material"));
}

TEST_CASE("stress-test walks a UMAT: the D-P UMAT passes, wrong ranges and tangents are caught", "[umat]") {
  const UmatModel dp = std::get<UmatModel>(umat_material(
      SOILSPH_UMAT_DRUCKER_PRAGER_F, "props = [1.0e6, 0.3, 35.0, 5000.0, 5.0]\nstate_variables = 1\n"));
  StressTestOptions options;
  options.increments = 2000;
  // STATEV(1), the accumulated plastic multiplier, is never negative.
  options.state_ranges = {{.index = 1, .lo = 0.0, .hi = 1e300}};
  const StressTestResult sound = run_umat_stress_test(dp, options);
  CAPTURE(sound.first_problem);
  CHECK(sound.failures == 0);
  CHECK(sound.violations == 0);
  CHECK(sound.tangent_checks == 200);
  CHECK(sound.worst_tangent_error < 1e-5);  // the consistent tangent of the return
  // A range it leaves (the multiplier grows past 1e-6 on the first plastic increments) is a violation.
  options.state_ranges = {{.index = 1, .lo = 0.0, .hi = 1e-6}};
  CHECK(run_umat_stress_test(dp, options).violations > 0);
  // A UMAT whose DDSDDE is zero for every increment fails the tangent check on every comparison.
  const UmatModel zero = std::get<UmatModel>(umat_material(
      kElasticC, "symbol = \"umat_elastic_c\"\nname = \"ZERO-TANGENT\"\nprops = [1.0e6, 0.3]\n"));
  options.state_ranges.clear();
  const StressTestResult wrong = run_umat_stress_test(zero, options);
  CHECK(wrong.tangent_mismatches == wrong.tangent_checks);
  CHECK(wrong.worst_tangent_error == Approx(1.0));
}
#endif
