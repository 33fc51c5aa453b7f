// The input fuzzer (docs/method/fuzzing.md): the harness's own checks, then the fuzz run.
#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <iostream>

#include "tests/fault/fuzz.h"

namespace {
namespace fs = std::filesystem;
using namespace soilsph::fuzz;

const std::string kExe = SOILSPH_EXECUTABLE;
const std::string kSource = SOILSPH_SOURCE_DIR;
const fs::path kWork = SOILSPH_FUZZ_WORK_DIR;

fs::path scratch(const std::string& name) {
  const fs::path dir = kWork / "harness" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}
}  // namespace

TEST_CASE("fuzz harness: a child's exit status, signal, hang and output are seen", "[fuzz][harness]") {
  const fs::path dir = scratch("child");
  Limits limits;
  limits.timeout_seconds = 1.0;
  const Outcome ok = run_child("/bin/sh", {"-c", "echo out; echo 'error: bad' >&2; exit 2"}, dir, limits);
  CHECK(ok.status == Outcome::Status::Exited);
  CHECK(ok.code == 2);
  CHECK(ok.out == "out\n");
  CHECK(last_line(ok.err) == "error: bad");
  const Outcome segv = run_child("/bin/sh", {"-c", "kill -SEGV $$"}, dir, limits);
  CHECK(segv.status == Outcome::Status::Signalled);
  CHECK(segv.code == SIGSEGV);
  const Outcome hang = run_child("/bin/sh", {"-c", "sleep 30 & sleep 30"}, dir, limits);
  CHECK(hang.status == Outcome::Status::Hang);
  CHECK(hang.seconds < 5.0);
  // CPU time is measured: a busy loop of 0.3 s of CPU takes at least that much wall time.
  const Outcome busy =
      run_child("/bin/sh", {"-c", "end=$(($(date +%s%N) + 300000000)); while [ $(date +%s%N) -lt $end ]; do :; done"},
                dir, limits);
  CHECK(busy.status == Outcome::Status::Exited);
  CHECK(busy.cpu_seconds > 0.0);
  CHECK(busy.cpu_seconds <= busy.seconds + 0.05);
  CHECK(calibrated_limits(limits, 3.0).timeout_seconds == 3.0);
  CHECK(calibrated_limits(limits, 0.5).timeout_seconds == 1.0);  // never below the idle limit
  const Outcome omp = run_child("/bin/sh", {"-c", "echo $OMP_NUM_THREADS; pwd"}, dir, limits);
  CHECK(omp.out == "1\n" + fs::canonical(dir).string() + "\n");
}

TEST_CASE("fuzz harness: the outcome rules", "[fuzz][harness]") {
  Case c;
  c.command = "material";
  c.expect = Expect::InputError;
  c.expect_why = "test";
  c.names_if_input = {{"the file", {"x.toml"}}};
  Outcome o;
  o.status = Outcome::Status::Exited;
  o.code = 2;
  o.err = "error: x.toml: [material] density is missing\n";
  CHECK(check(c, o, ".").empty());
  o.code = 1;
  REQUIRE(check(c, o, ".").size() == 1);
  CHECK(check(c, o, ".").front().category == "input-error-exit-1");
  o.code = 2;
  o.err = "--increments: Value 0 not in range\nRun with --help for more information.\n";
  CHECK(check(c, o, ".").front().category == "no-error-line");
  o.err = "error: std::bad_alloc\n";
  bool library = false;
  for (const Finding& f : check(c, o, ".")) library = library || f.category == "message-library-text";
  CHECK(library);
  o.code = 0;
  o.err.clear();
  CHECK(check(c, o, ".").front().category == "bad-input-accepted");
  o.code = 3;
  CHECK(check(c, o, ".").front().category == "exit-status");
  o.status = Outcome::Status::Signalled;
  o.code = SIGABRT;
  CHECK(check(c, o, ".").front().category == "signal");
}

TEST_CASE("fuzz harness: the output checks catch silent wrong results", "[fuzz][harness]") {
  // Synthetic outputs (no soilsph run): each must give a finding of its category.
  const fs::path dir = scratch("outputs");
  std::ofstream(dir / "dp.toml") << "[material]\nmodel = \"drucker-prager\"\nfriction_angle = 35.0\n";
  const auto categories = [&](const Case& c, const Outcome& o) {
    std::string all;
    for (const Finding& f : check(c, o, dir)) all += f.category + " ";
    return all;
  };
  Outcome o;
  o.status = Outcome::Status::Exited;
  o.code = 0;
  Case point;
  point.command = "point";
  point.toml_path = "dp.toml";
  point.test = "triaxial-undrained";
  point.increments = 1;
  const std::string head =
      "# soilsph point: x\neps_a,eps_r,eps_v,eps_q,sig_a,sig_r,p,q,p_c,u,tau_xy,gamma_xy\n"
      "0,0,0,0,100000,100000,100000,0,0,0,0,0\n";
  o.out = head +
          "0.1,-0.05,0,0.1,162873.12639873853,68563.436800630734,100000,94309.689598107798,0,31436."
          "563199369266,0,0\n";
  CHECK(categories(point, o).empty());
  o.out = head + "0.1,-0.05,0,0.1,-0,-0,-0,0,0,100000,0,0\n";  // D-P without dilatancy: p' must stay
  CHECK(categories(point, o) == "point-output ");
  o.out = head + "0.1,-0.05,0,0.1,nan,68563,100000,94310,0,31437,0,0\n";
  CHECK(categories(point, o) == "point-output ");
  o.out = head;  // a row short
  CHECK(categories(point, o) == "point-output ");
  Case material;
  material.command = "material";
  o.out =
      "m.toml: drucker-prager, density 2000 kg/m^3\n  K = 833333 Pa, G = 0 Pa\n  alpha_phi = 0.18, k_c = inf "
      "Pa\n";
  CHECK(categories(material, o) == "material-output material-output ");
  Case collapse;
  collapse.command = "collapse";
  collapse.out_dir = "out";
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "frames.h5") << "x";
  std::ofstream(dir / "out" / "frames.xdmf") << "x";
  std::ofstream(dir / "out" / "summary.json") << "{\n  \"steps\": 0,\n  \"time_step\": null,\n"
                                                 "  \"guard_corrections\": 3\n}\n";
  o.out.clear();
  const std::string found = categories(collapse, o);
  CHECK(found.find("collapse-output") != std::string::npos);
  CHECK(found.find("collapse-blowup") != std::string::npos);
}

TEST_CASE("fuzz harness: a case is a function of (seed, index)", "[fuzz][harness]") {
  const Inputs inputs = Inputs::load(kSource);
  std::size_t differ = 0;
  for (std::uint64_t index = 0; index < 200; ++index) {
    const Case a = make_case(inputs, 7, index), b = make_case(inputs, 7, index);
    REQUIRE(a.args == b.args);
    REQUIRE(a.mutations == b.mutations);
    REQUIRE(a.files.size() == b.files.size());
    for (std::size_t k = 0; k < a.files.size(); ++k) REQUIRE(a.files[k].content == b.files[k].content);
    const Case other = make_case(inputs, 8, index);
    differ += other.args != a.args || other.mutations != a.mutations;
  }
  CHECK(differ > 150);
}

TEST_CASE("fuzz harness: the cases of a long run can all be made", "[fuzz][harness]") {
  // The generator alone (no run) over more cases than the documented long run, so that a mutation
  // of an already mutated file cannot crash it hours into a run.
  const Config config = Config::from_environment(kExe, kSource, kWork);
  const Inputs inputs = Inputs::load(kSource);
  std::size_t files = 0;
  for (std::uint64_t index = 0; index < std::max<std::uint64_t>(12000, config.first + config.count); ++index)
    files += make_case(inputs, config.seed, index).files.size();
  CHECK(files > 0);
}

TEST_CASE("fuzz harness: every unmutated input passes every check", "[fuzz][harness]") {
  // The control: the shipped inputs, all commands, tests and integrators. A finding here is a false
  // alarm of the checks (or a regression of soilsph on its own inputs), not a fuzz finding.
  const Inputs inputs = Inputs::load(kSource);
  const fs::path root = scratch("base");
  Config config = Config::from_environment(kExe, kSource, kWork);
  config.limits.timeout_seconds = 30;
  const Limits limits = calibrated_limits(config.limits, measured_slowdown(config, root));
  for (const Case& c : base_cases(inputs)) {
    const fs::path dir = root / ("base-" + std::to_string(c.index));
    fs::create_directories(dir);
    for (const File& f : c.files) std::ofstream(dir / f.name, std::ios::binary) << f.content;
    const Outcome o = run_child(kExe, c.args, dir, limits);
    INFO(command_line(kExe, c, dir) << "\nstderr: " << o.err);
    CHECK(o.status == Outcome::Status::Exited);
    CHECK(o.code == 0);
    for (const Finding& f : check(c, o, dir)) FAIL_CHECK(f.category << ": " << f.detail);
  }
}

TEST_CASE("input fuzzer: every mutant ends with 0, 1 or 2, a message, and sane results", "[fuzz][input]") {
  const Config config = Config::from_environment(kExe, kSource, kWork);
  const RunReport report = run(config);
  std::cout << report.text << std::flush;
  CHECK(report.cases == (config.only.empty() ? config.count : config.only.size()));
  INFO(report.text);
  CHECK(report.failures.empty());
}
