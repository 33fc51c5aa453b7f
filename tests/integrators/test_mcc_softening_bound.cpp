// MCC's softening bound (`minimum_preconsolidation`, modified_cam_clay.h): on a heavily
// overconsolidated drained triaxial path the dry side softens until p_c reaches the bound, then the
// state stays where the stress path leaves the bound's ellipse. That point is a closed form, so every
// scheme and the CVODE reference are checked against it, and against the critical state the same
// path reaches without the bound.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/common/table1_materials.h"
#include "verification/point_test.h"
#include "verification/programme/programme_file.h"
#include "../common/temp_dir.h"

using namespace soilsph;
using namespace soilsph::verification;

namespace {
constexpr double kP0 = 100e3, kOcr = 10.0, kBound = 500e3;  // Pa; p_c0 = 1 MPa

PointTest drained_path() {
  PointTest t;
  t.path = LoadPath::TriaxialDrained;
  t.p_initial = kP0;
  t.ocr = kOcr;
  t.strain_targets = {0.3};
  t.increments = 300;
  return t;
}

Material cam_clay(double bound, Integrator integrator) {
  ModifiedCamClay::Params p = test::table1_cam_clay_params(Elasticity::Kind::PressureDependent);
  p.minimum_preconsolidation = bound;
  p.integrator = integrator;
  return Material(ModifiedCamClay(p));
}

/// Where the drained path q = 3(p − p0) leaves the ellipse M²p(p − p_c) + q² = 0: the larger root
/// of (M² + 9)p² − (M² p_c + 18 p0)p + 9p0² = 0 (p0 lies between the roots: f(p0) < 0).
double exit_pressure(double M, double pc) {
  const double a = M * M + 9.0, b = -(M * M * pc + 18.0 * kP0), c = 9.0 * kP0 * kP0;
  return (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
}
}  // namespace

TEST_CASE("MCC softening stops at minimum_preconsolidation: the drained dry side ends on the bound's ellipse",
          "[integrators][cvode]") {
  const double M = ModifiedCamClay(test::table1_cam_clay_params()).M();
  // Without the bound the path softens to the critical state q = M p: p = p0/(1 − M/3), p_c = 2p
  // (379 kPa), below the bound, so the bound must act.
  const double p_critical = kP0 / (1.0 - M / 3.0);
  REQUIRE(2.0 * p_critical < kBound);
  const double p_end = exit_pressure(M, kBound), q_end = 3.0 * (p_end - kP0);
  REQUIRE(2.0 * p_end < kBound);  // on the dry side, where the flow dilates and would soften further

  for (const char* scheme : {"explicit", "substep", "implicit", "cvode"}) {
    INFO(scheme);
    const Integrator integrator = std::string_view(scheme) == "cvode" ? Integrator::Implicit : parse_integrator(scheme);
    const PointRecord bounded = run_point_test(cam_clay(kBound, integrator), drained_path(), scheme).back();
    CHECK(bounded.p_c == Approx(kBound).epsilon(1e-6));
    CHECK(bounded.p == Approx(p_end).epsilon(1e-4));
    CHECK(bounded.q == Approx(q_end).epsilon(1e-4));
    // Without the bound the same path softens on towards the critical state, which it approaches
    // asymptotically (by ε_a = 0.3 within 0.3 % in p, CVODE and every scheme alike).
    const PointRecord free = run_point_test(cam_clay(0.0, integrator), drained_path(), scheme).back();
    CHECK(free.p == Approx(p_critical).epsilon(5e-3));
    CHECK(free.p_c == Approx(2.0 * p_critical).epsilon(1e-2));
    CHECK(free.p_c < 0.8 * kBound);
  }
}

TEST_CASE("MCC softening bound: p_c never below it, compaction still hardens from it", "[constitutive]") {
  ModifiedCamClay::Params p = test::table1_cam_clay_params();
  p.minimum_preconsolidation = 1e3;
  const ModifiedCamClay mcc(p);
  // hardened(): eq 27 above the bound, the bound below it, and a start already below softens no further.
  CHECK(mcc.hardened(2e3, 0.01) == Approx(2e3 * std::exp(mcc.hardening_exponent() * 0.01)));
  CHECK(mcc.hardened(2e3, -0.01) == Approx(2e3 * std::exp(-mcc.hardening_exponent() * 0.01)));
  CHECK(mcc.hardened(2e3, -1.0) == 1e3);
  CHECK(mcc.hardened(500.0, -0.01) == 500.0);
  CHECK(mcc.hardened(1e3, 0.01) == Approx(1e3 * std::exp(mcc.hardening_exponent() * 0.01)));
  // The rate form: softening stops at the bound, compaction hardens.
  CHECK(mcc.hardening_exponent_at(1e3, -1.0) == 0.0);
  CHECK(mcc.hardening_exponent_at(1e3, 1.0) == mcc.hardening_exponent());
  CHECK(mcc.hardening_exponent_at(1.5e3, -1.0) == mcc.hardening_exponent());
  // Validated where the model is built, naming the key.
  ModifiedCamClay::Params negative = p;
  negative.minimum_preconsolidation = -1.0;
  CHECK_THROWS_WITH(ModifiedCamClay(negative), Catch::Contains("minimum_preconsolidation"));
  // The initial p_c of a nearly stress-free state is the bound.
  CHECK(mcc.initial_preconsolidation(isotropic_stress(10.0), 1.0) == 1e3);
  // A dust-like state (p = 100 Pa on the loosest surface, p_c = 1 kPa) sheared far past yield returns
  // to the bound's ellipse, not below it, for every scheme.
  for (Integrator integrator : {Integrator::Explicit, Integrator::Substep, Integrator::Implicit}) {
    p.integrator = integrator;
    const ModifiedCamClay model(p);
    State s;
    s.stress = isotropic_stress(100.0);
    s.pc = 1e3;
    Mat3 shear = Mat3::Zero();
    shear(0, 1) = shear(1, 0) = 0.02;
    const State next = model.update(s, shear, Mat3::Zero());
    INFO(integrator_name(integrator));
    CHECK(next.pc >= 1e3 * (1.0 - 1e-12));
    CHECK(model.normalized_yield(next.stress, next.pc) <= 1e-6);
  }
}

TEST_CASE("MCC softening bound under cyclic shear: CVODE stops softening at the bound and follows the implicit return",
          "[integrators][cvode]") {
  // Drained cyclic simple shear (the shipped programme's soil, OCR 4, γ = ±5 %, five cycles): the dry
  // side softens p_c from 400 kPa onto the bound of 300 kPa, where CVODE's rate jumps to 0 (it once
  // failed there, "corrector convergence test failed", until the bound became a root of its
  // switching function).
  const soilsph::testing::TempDir dir("soilsph-bounded-cyclic");
  auto programme = [&dir](double bound) {
    const std::filesystem::path path = dir / ("bounded-cyclic-" + std::to_string(bound) + ".toml");
    std::ofstream(path) << "[material]\nmodel = \"modified-cam-clay\"\ndensity = 2000.0\npoisson_ratio = 0.3\n"
                           "friction_angle = 30.0\ncompression_index = 0.085\nswelling_index = 0.019\n"
                           "initial_void_ratio = 0.68\nelasticity = \"pressure-dependent\"\n"
                           "minimum_preconsolidation = " << bound << "\n"
                           "[initial]\nvertical_stress = 100e3\nocr = 4.0\n"
                           "[[leg]]\nincrements = 50\nstress = { xx = \"hold\" }\nstrain = { xy = [0.05, -0.05] }\n"
                           "repeat = 5\n";
    return read_programme_file(path.string());
  };
  const double bound = 300e3;
  const ProgrammeFile bounded = programme(bound);
  const PointCurve reference = run_programme(bounded.material, bounded.programme, "cvode");
  const PointCurve implicit = run_programme(bounded.material, bounded.programme, "implicit");
  REQUIRE(reference.size() == implicit.size());
  double dp = 0, dq = 0, sp = 0, sq = 0, lowest = reference.front().p_c;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    dp = std::max(dp, std::abs(implicit[k].p - reference[k].p)), sp = std::max(sp, std::abs(reference[k].p));
    dq = std::max(dq, std::abs(implicit[k].q - reference[k].q)), sq = std::max(sq, std::abs(reference[k].q));
    lowest = std::min(lowest, reference[k].p_c);
  }
  INFO("p error " << dp / sp << ", q error " << dq / sq << ", lowest p_c " << lowest);
  CHECK(lowest == Approx(bound).epsilon(1e-9));  // reached, never passed
  CHECK(implicit.back().p_c == Approx(bound).epsilon(1e-9));
  CHECK(dp / sp < 1e-3);  // measured 6e-5
  CHECK(dq / sq < 1e-3);  // measured 1e-4
  // Without the bound the same programme softens further.
  const ProgrammeFile free = programme(0.0);
  CHECK(run_programme(free.material, free.programme, "cvode").back().p_c < 0.9 * bound);
}
