#pragma once
/// @file
/// The input fuzzer: mutants of the shipped inputs (TOML materials, the strain-path
/// CSV, a small collapse scene) and of the command line, each run through the `soilsph` executable in a
/// child process with a time limit, and the contract checked from outside:
/// - the process ends by itself (no signal, no hang) with exit status 0, 1 or 2;
/// - a non-zero exit has a line starting with `error:` on stderr that names what was wrong;
/// - an input the harness knows to be invalid ends with 2 (input error), not 1 or 0;
/// - an exit 0 has sane results (finite numbers, the rows asked for, the test's imposed conditions,
///   a summary.json that reached the end time without the wall guard acting unreported).
/// Every case is a pure function of (seed, index), so a failure is reproduced by its index alone.
/// docs/method/fuzzing.md describes the mutations, the outcome classes and how to run it.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace soilsph::fuzz {

namespace fs = std::filesystem;

/// What the harness knows about the right exit status of a case.
enum class Expect {
  Any,         ///< 0, 1 or 2 may all be right (e.g. a huge but admissible value)
  InputError,  ///< the input is invalid (bad file, key, value or command line): exit 2
  Failure,     ///< must not succeed: exit 1 or 2 (e.g. an output folder that cannot be created)
};

/// Strings of which a non-zero exit's `error:` line must hold at least one (e.g. the file or the key).
struct NameGroup {
  std::string what;                 ///< in words, for the report ("the file", "the key")
  std::vector<std::string> any_of;  ///< compared case-sensitively
};

struct File {
  std::string name;  ///< relative to the case folder
  std::string content;
};

/// One fuzz case: the files to write, the command line, what the harness expects, and what the output
/// checks need to know.
struct Case {
  std::uint64_t seed = 0;
  std::uint64_t index = 0;
  std::string kind;  ///< material, point, strain-path, programme, collapse, cli-point, cli-collapse
  std::vector<std::string> mutations;  ///< each mutation in words
  std::vector<File> files;             ///< written into the case folder before the run
  std::vector<std::string> args;       ///< the arguments after the executable
  Expect expect = Expect::Any;
  std::string expect_why;                  ///< why the harness expects what it expects
  std::vector<NameGroup> names_if_input;   ///< an exit 2's error line must match each group
  std::vector<NameGroup> names_if_failed;  ///< any non-zero exit's error line must match each group

  // What the output checks need.
  std::string command;                 ///< material, point or collapse
  std::string toml_path;               ///< the TOML input (relative to the case folder or absolute)
  std::vector<std::string> overrides;  ///< the --set assignments given, in order
  std::string test;                    ///< point: the --test name
  int legs = 1;                        ///< point: number of --strain-max targets
  long long increments = 20;           ///< point: increments per leg
  long long strain_rows = -1;          ///< point strain-path: data rows of the CSV if known, else -1
  double p_initial = 100e3;            ///< point: --p-initial as run
  double ocr = 1.0;                    ///< point: --ocr as run
  bool ocr_given = false;              ///< point: --ocr was on the command line
  std::string out_dir;                 ///< collapse: the --out folder (relative to the case folder)
};

/// The shipped inputs the mutants start from, read once.
/// A collapse scene of the fuzzer: its case file name, its text, and files it reads beside it.
struct SceneInput {
  std::string name, text;
  std::vector<File> files;  ///< e.g. the particle CSV of a `shape = "particles"` region
};

struct Inputs {
  std::string source_dir;  ///< the project's source tree (for the unmutated files' absolute paths)
  std::string material_dp, material_mcc;  ///< data/materials/{dp,mcc}-table1.toml
  std::string strain_csv;                 ///< data/strain-paths/simple-shear.csv
  std::string scene_dp, scene_mcc;        ///< data/scenes/collapse-{dp,mcc}.toml made small (below)
  /// Other shipped scenes (regions, gates, several materials, Mohr-Coulomb, imported particles), made
  /// small, by their case file names scene-NAME.toml
  std::vector<SceneInput> other_scenes;
  /// data/programmes/*.toml by name, their material paths made absolute (programme_with_absolute_material)
  std::vector<std::pair<std::string, std::string>> programmes;
  static Inputs load(const std::string& source_dir);
};

/// A shipped collapse scene made small: particle_spacing 0.004 (or `spacing`, for a geometry it
/// does not divide), end_time 0.02, frame_interval 0.01, and a run-time budget max_run_hours = 0.002 (7 s).
std::string small_scene(const std::string& scene_toml, const std::string& spacing = "0.004");

/// The case of `index` under `seed`: the same pair always gives the same case.
Case make_case(const Inputs& inputs, std::uint64_t seed, std::uint64_t index);
/// The unmutated runs (every command on every shipped input); they must all pass the checks.
std::vector<Case> base_cases(const Inputs& inputs);

/// How a child process ended.
struct Outcome {
  enum class Status { Exited, Signalled, Hang, NotStarted } status = Status::NotStarted;
  int code = 0;  ///< exit status, or the signal number
  double seconds = 0.0;
  double cpu_seconds = 0.0;  ///< user + system CPU time of the child (0 if it did not end by itself)
  std::string out, err;  ///< the child's stdout and stderr (first 1 MB each)
};

/// Limits of a child: wall time; address space (so that a runaway allocation fails at once instead of
/// swapping the shared machine); file size (output of runs that never stop).
struct Limits {
  /// On an idle machine: an unmutated case takes 0.1 s, the largest valid one about 5 s. A run scales
  /// it by the machine's load as measured by a calibration run (calibrated_limits).
  double timeout_seconds = 20.0;
  std::uint64_t address_space_bytes = 4ull << 30;
  std::uint64_t file_size_bytes = 1ull << 30;
};

/// Runs `executable args...` in `dir` with stdin from /dev/null, stdout and stderr to files there, one
/// OpenMP thread, and `limits`; kills the child's process group when it exceeds the time.
Outcome run_child(const std::string& executable, const std::vector<std::string>& args, const fs::path& dir,
                  const Limits& limits);

/// One broken promise found in a case.
struct Finding {
  std::string category;  ///< a fixed name (docs/method/fuzzing.md lists them)
  std::string detail;
};

/// The checks of a case's outcome (`dir` holds the case's files and output).
std::vector<Finding> check(const Case& c, const Outcome& outcome, const fs::path& dir);

/// Shell form of one case's command (cd to its folder, then the executable and its arguments).
std::string command_line(const std::string& executable, const Case& c, const fs::path& dir);
/// The last non-empty line of `text`.
std::string last_line(const std::string& text);

/// A run of many cases.
struct Config {
  std::string executable;
  std::string source_dir;
  fs::path work_dir;  ///< cases/ (scratch, each removed when it passes) and failures/ (kept)
  std::uint64_t seed = 20260610;
  std::uint64_t first = 0;
  std::uint64_t count = 240;
  std::vector<std::uint64_t> only;  ///< when not empty: just these case indices
  int jobs = 2;
  bool keep_all = false;  ///< keep every case folder, not only the failing ones
  bool verbose = false;   ///< print every case
  Limits limits;
  /// The environment's SOILSPH_FUZZ_* settings over the defaults (docs/method/fuzzing.md).
  static Config from_environment(std::string executable, std::string source_dir, fs::path default_work_dir);
};

struct CaseResult {
  Case c;
  Outcome outcome;
  std::vector<Finding> findings;
};

struct RunReport {
  std::uint64_t cases = 0;
  double seconds = 0.0;
  double slowdown = 1.0;          ///< the calibration's measured_slowdown
  double timeout_seconds = 0.0;   ///< the time limit the cases ran with (calibrated)
  std::vector<CaseResult> failures;  ///< in index order
  std::size_t exit_counts[3] = {0, 0, 0};
  std::string text;  ///< the summary by category (also written to failures/REPORT.md)
};

/// How much slower than its own CPU time a run of the small unmutated D-P collapse (the fuzzer's
/// commonest heavy case) goes now, with `jobs` copies at once as the fuzz run has: wall / CPU seconds
/// of the slowest copy, at least 1. On a machine shared by more processes than cores, every child's
/// wall time stretches by this factor, valid or not.
double measured_slowdown(const Config& config, const fs::path& dir);
/// `limits` with the time limit stretched by the slowdown, so that a valid case on a loaded machine
/// is not taken for a hang while a real hang (CPU-bound or blocked) is still killed.
Limits calibrated_limits(Limits limits, double slowdown);

/// Runs the cases of `config` (in parallel), keeps each failing case's folder under failures/ with its
/// command, and writes failures/REPORT.md and failures/failures.tsv.
RunReport run(const Config& config);

}  // namespace soilsph::fuzz
