// Fault tests of `soilsph collapse` as a user meets them: a signal or kill -9 mid-run, a full disk,
// a blow-up, a rerun into a used folder, a resume that would change the run. Each runs the
// executable as a child process on a coarse scene (4 mm, 176 particles) and reads what it left.
#include <hdf5.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "child_process.h"

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using soilsph::test::ChildOptions;
using soilsph::test::run_child;

namespace {

const fs::path kRoot = fs::path(SOILSPH_FAULT_DIR);

/// A fresh folder for one test's runs.
fs::path fresh(const std::string& name) {
  const fs::path dir = kRoot / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// The D-P collapse at 4 mm to 1.5 s without stopping at rest (about 15 000 steps, a second or two),
/// checkpoints every 0.05 s, into `out`.
std::vector<std::string> collapse(const fs::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{SOILSPH_EXECUTABLE,
                                "collapse",
                                SOILSPH_SOURCE_DIR "/data/scenes/collapse-dp.toml",
                                "--threads",
                                "1",
                                "--out",
                                out.string(),
                                "--set",
                                "scene.particle_spacing=0.004",
                                "--set",
                                "scene.stop_at_rest=false",
                                "--set",
                                "scene.end_time=1.5",
                                "--set",
                                "output.checkpoint_interval=0.05"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

std::vector<std::string> resume(const fs::path& dir) {
  return {SOILSPH_EXECUTABLE, "collapse", "--threads", "1", "--resume", dir.string()};
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

/// The datasets of a frame of a 2D run, and of a 3D run (frame_writer.h).
const std::vector<std::string> kPlaneSets{"position", "id", "velocity", "sxx", "syy", "szz", "sxy", "p", "q", "density"};
const std::vector<std::string> kSpaceSets{"position", "id",  "velocity", "sxx", "syy", "szz",
                                          "sxy",      "sxz", "syz",      "p",   "q",   "density"};

/// Every dataset `sets` of every frame of DIR/frames.h5, read back (throws if any cannot be);
/// returns the last frame's datasets by name and the number of frames.
struct Frames {
  std::size_t count = 0;
  std::vector<double> times;  ///< each frame's simulated time, in order
  std::map<std::string, std::vector<double>> last;
};

Frames read_frames(const fs::path& dir, const std::vector<std::string>& sets = kPlaneSets) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen((dir / "frames.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot open " + (dir / "frames.h5").string());
  Frames frames;
  for (;; ++frames.count) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu", frames.count);
    if (H5Lexists(file, name, H5P_DEFAULT) <= 0) break;
    double time = 0.0;
    const hid_t attribute = H5Aopen_by_name(file, name, "time", H5P_DEFAULT, H5P_DEFAULT);
    if (attribute < 0 || H5Aread(attribute, H5T_NATIVE_DOUBLE, &time) < 0)
      throw std::runtime_error(std::string("cannot read the time of ") + name);
    H5Aclose(attribute);
    frames.times.push_back(time);
    frames.last.clear();
    for (const std::string& set : sets) {
      const hid_t d = H5Dopen2(file, (std::string(name) + "/" + set).c_str(), H5P_DEFAULT);
      if (d < 0) throw std::runtime_error(std::string("cannot open ") + name + "/" + set);
      const hid_t space = H5Dget_space(d);
      std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      const herr_t status = H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
      H5Sclose(space);
      H5Dclose(d);
      if (status < 0) throw std::runtime_error(std::string("cannot read ") + name + "/" + set);
      frames.last[set] = std::move(values);
    }
  }
  H5Fclose(file);
  return frames;
}

/// The number in `json` after `"key": ` (a summary.json field).
double json_number(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  const std::size_t at = json.find(tag);
  if (at == std::string::npos) throw std::runtime_error("no " + key + " in the summary");
  return std::stod(json.substr(at + tag.size()));
}

/// Frames at 0, interval, ..., end, each once (a frame is written at the step within half a step
/// dt of its time), plus the one at `stop` when that step is not also one of them.
void check_frame_times(const std::vector<double>& times, double interval, double end, double dt,
                       double stop) {
  const auto regular = static_cast<std::size_t>(std::lround(end / interval)) + 1;
  std::vector<int> seen(regular, 0);
  std::size_t other = 0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (k > 0) CHECK(times[k] > times[k - 1]);
    const long nearest = std::lround(times[k] / interval);
    if (nearest >= 0 && static_cast<std::size_t>(nearest) < regular &&
        std::abs(times[k] - nearest * interval) <= 0.5 * dt + 1e-12)
      ++seen[static_cast<std::size_t>(nearest)];
    else {
      ++other;
      CHECK(times[k] == Approx(stop).epsilon(1e-5));  // the log prints 6 digits
    }
  }
  for (std::size_t k = 0; k < regular; ++k) {
    INFO("frame time " << static_cast<double>(k) * interval);
    CHECK(seen[k] == 1);
  }
  CHECK(other <= 1);
  if (other == 0) CHECK(std::abs(stop - std::lround(stop / interval) * interval) <= 0.5 * dt + 1e-5 * stop);
}

/// The last frame of the same run uninterrupted, in its own folder (ctest runs test cases in parallel).
void check_bit_identical(const Frames& resumed, const std::string& test,
                         std::vector<std::string> extra = {}) {
  const fs::path dir = fresh(test + "-uninterrupted");
  REQUIRE(run_child(collapse(dir, extra), dir / "log.txt").exit_status == 0);
  const Frames full = read_frames(dir);
  REQUIRE(resumed.last.size() == full.last.size());
  for (const auto& [name, values] : full.last) {
    INFO(name);
    CHECK(resumed.last.at(name) == values);  // exact: every bit
  }
}

}  // namespace

TEST_CASE("SIGTERM: the run stops cleanly, and resumed it ends bit for bit as one that never stopped",
          "[fault][resume]") {
  const fs::path dir = fresh("sigterm");
  ChildOptions kill_early;
  kill_early.signal_when_exists = dir / "checkpoint.h5";
  kill_early.signal = SIGTERM;
  const auto stopped = run_child(collapse(dir), dir / "log.txt", kill_early);
  INFO(stopped.log);
  REQUIRE(stopped.exit_status == 143);
  CHECK_THAT(stopped.log, Contains("stopped by SIGTERM at t = ") && Contains("--resume " + dir.string()));
  const std::string summary = text_of(dir / "summary.json");
  CHECK_THAT(summary, Contains("\"complete\": false") && Contains("\"stop_reason\": \"signal SIGTERM\""));
  CHECK(read_frames(dir).count >= 2);
  const auto resumed = run_child(resume(dir), dir / "resume-log.txt");
  INFO(resumed.log);
  REQUIRE(resumed.exit_status == 0);
  CHECK_THAT(text_of(dir / "summary.json"), Contains("\"complete\": true") &&
                                                Contains("\"end_time\": 1.5,") &&
                                                !Contains("\"resumed_from\": null"));
  // t = 0, 0.01, ..., 1.5, none lost or twice, and the frame at the stop unless that step was one of
  // them anyway (about one run in a hundred: 1 % of the steps write a frame).
  const Frames frames = read_frames(dir);
  const std::string marker = "stopped by SIGTERM at t = ";
  const double stop = std::stod(stopped.log.substr(stopped.log.find(marker) + marker.size()));
  check_frame_times(frames.times, 0.01, 1.5, json_number(text_of(dir / "summary.json"), "largest_time_step"),
                    stop);
  check_bit_identical(frames, "sigterm");
}

TEST_CASE("kill -9: every file left is readable, and the run resumes from its last checkpoint bit for bit",
          "[fault][resume]") {
  const fs::path dir = fresh("kill9");
  ChildOptions kill_hard;
  kill_hard.signal_when_exists = dir / "checkpoint.h5";
  kill_hard.signal = SIGKILL;
  // Frames every 40th step: much of the wall time goes into frame writes, so the kill often lands
  // inside one (the case that could tear a frame file before each file was written whole).
  // A dilatant soil with a cut-off, so that the resumed run is bit-identical only if the checkpoint
  // keeps each particle's plastic dilation too.
  const std::vector<std::string> dense_frames{"--set", "output.frame_interval=0.004",
                                              "--set", "material.dilatancy_angle=10",
                                              "--set", "material.dilatancy_cutoff=0.02"};
  const auto killed = run_child(collapse(dir, dense_frames), dir / "log.txt", kill_hard);
  REQUIRE(killed.signal == SIGKILL);
  CHECK_NOTHROW(read_frames(dir));
  // The record written at the start says the run never finished.
  CHECK_THAT(text_of(dir / "summary.json"),
             Contains("\"complete\": false") && Contains("\"stop_reason\": \"running\""));
  const auto resumed = run_child(resume(dir), dir / "resume-log.txt");
  INFO(resumed.log);
  REQUIRE(resumed.exit_status == 0);
  const Frames frames = read_frames(dir);
  CHECK(frames.count == 376);  // t = 0, 0.004, ..., 1.5: none lost, none twice
  check_bit_identical(frames, "kill9", dense_frames);
}

TEST_CASE("a full disk ends the run with one line, and the frames written before stay readable",
          "[fault][disk]") {
  const fs::path dir = fresh("disk-full");
  ChildOptions small;
  // A file-size limit (ulimit -f, per file) that a frame (28 kB) fits in and the first checkpoint
  // (92 kB, due at t = 0.05 s) does not: the disk is "full" mid-run.
  small.file_size_limit = 60 * 1024;
  const auto r = run_child(collapse(dir), dir / "log.txt", small);
  INFO(r.log);
  CHECK(r.signal == 0);
  CHECK(r.exit_status == 1);
  CHECK_THAT(r.log, Contains("error: ") &&
                        Contains("checkpoint.h5.tmp would grow past this process's file-size limit"));
  CHECK(r.log.find("HDF5-DIAG") == std::string::npos);  // HDF5's own error stack stays silent
  const Frames frames = read_frames(dir);
  CHECK(frames.count == 6);  // t = 0 ... 0.05
  CHECK_FALSE(fs::exists(dir / "checkpoint.h5"));
  CHECK_THAT(text_of(dir / "summary.json"), Contains("\"complete\": false") && Contains("file-size limit"));
  for (const auto& entry : fs::recursive_directory_iterator(dir)) CHECK(entry.path().extension() != ".tmp");
}

namespace {

/// The summary of a run that failed at "(step N, t = T s)" in its log reports the N - 1 steps that
/// closed and the time T they reached, not the starting figures.
void check_failed_summary(const fs::path& dir, const std::string& log) {
  const std::size_t at = log.find("(step ");
  REQUIRE(at != std::string::npos);
  std::istringstream named(log.substr(at + 6));
  double failed_step = 0.0, time = 0.0;
  std::string comma, t, equals;
  named >> failed_step >> comma >> t >> equals >> time;  // "N, t = T s)"
  REQUIRE(named);
  const std::string summary = text_of(dir / "summary.json");
  CHECK(failed_step > 1.0);
  CHECK(json_number(summary, "steps") == failed_step - 1.0);
  CHECK(json_number(summary, "end_time") == Approx(time).margin(5e-7));  // the log prints 6 decimals
  CHECK(json_number(summary, "wall_seconds") > 0.0);
  CHECK(json_number(summary, "smallest_time_step") > 0.0);
}

}  // namespace

TEST_CASE("a blow-up stops the run, naming the particle, quantity, step and time", "[fault][blow-up]") {
  const fs::path dir = fresh("blow-up");
  // Twice the CFL number at which the scheme is still stable (docs/validation/time-step.md).
  const auto r = run_child(collapse(dir, {"--set", "numerics.cfl=2.0"}), dir / "log.txt");
  INFO(r.log);
  CHECK(r.exit_status == 1);
  CHECK_THAT(r.log, Contains("error: blow-up: ") && Contains("soil particle") && Contains("(step ") &&
                        Contains("[numerics] cfl"));
  CHECK_THAT(text_of(dir / "summary.json"), Contains("\"complete\": false") && Contains("blow-up") &&
                                                Contains("\"runout_m\": null"));  // no deposit
  check_failed_summary(dir, r.log);
  CHECK_NOTHROW(read_frames(dir));
  CHECK(fs::exists(dir / "checkpoint.h5"));  // the last good checkpoint is kept
}

TEST_CASE("a rerun into a used folder leaves nothing of the old run beside the new one", "[fault][stale]") {
  const fs::path dir = fresh("stale");
  REQUIRE(run_child({SOILSPH_EXECUTABLE, "collapse", SOILSPH_SOURCE_DIR "/data/scenes/collapse-mcc.toml",
                     "--threads", "1", "--out", dir.string(), "--set", "scene.particle_spacing=0.004",
                     "--set", "scene.end_time=0.05"},
                    dir / "log.txt")
              .exit_status == 0);
  std::ofstream(dir / "deposit.png") << "a picture of the first run";
  // The second run, of the other model, blows up (at twice the stable CFL number).
  const auto r = run_child(collapse(dir, {"--set", "numerics.cfl=2.0"}), dir / "log2.txt");
  INFO(r.log);
  CHECK(r.exit_status == 1);
  const std::string summary = text_of(dir / "summary.json");
  CHECK_THAT(summary, Contains("\"model\": \"drucker-prager\"") && Contains("\"complete\": false") &&
                          Contains("blow-up"));
  CHECK_FALSE(fs::exists(dir / "deposit.png"));
  CHECK_THAT(text_of(dir / "scene.toml"), Contains("model = 'drucker-prager'"));
}

TEST_CASE("resuming refuses a change that would not continue the same run", "[fault][resume]") {
  const fs::path dir = fresh("resume-refused");
  REQUIRE(run_child(collapse(dir, {"--set", "scene.end_time=0.05"}), dir / "log.txt").exit_status == 0);
  auto args = resume(dir);
  args.insert(args.end(), {"--set", "material.friction_angle=30"});
  const auto r = run_child(args, dir / "resume-log.txt");
  CHECK(r.exit_status == 2);
  CHECK_THAT(r.log,
             Contains("--set material.friction_angle=30: material.friction_angle cannot change when a run is "
                      "resumed"));
}

TEST_CASE("resuming refuses a checkpoint of another format, naming both", "[fault][resume]") {
  const fs::path dir = fresh("resume-old-format");
  REQUIRE(run_child(collapse(dir, {"--set", "scene.end_time=0.05"}), dir / "log.txt").exit_status == 0);
  {  // relabel the checkpoint as one of the format before the plastic strain tensor was dropped
    const hid_t file = H5Fopen((dir / "checkpoint.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    REQUIRE(H5Adelete(file, "format") >= 0);
    const char* old_format = "soilsph checkpoint 1";
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, std::strlen(old_format));
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(file, "format", type, space, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(H5Awrite(attribute, type, old_format) >= 0);
    H5Aclose(attribute), H5Sclose(space), H5Tclose(type), H5Fclose(file);
  }
  const auto r = run_child(resume(dir), dir / "resume-log.txt");
  CHECK(r.exit_status != 0);
  CHECK_THAT(r.log,
             Contains("is not a soilsph checkpoint of this version (format \"soilsph checkpoint 4\", the "
                      "file's is \"soilsph checkpoint 1\"): rerun the scene"));
}

TEST_CASE("DIR/scene.toml reproduces the run", "[fault][record]") {
  const fs::path first = fresh("record-first"), second = fresh("record-second");
  REQUIRE(run_child(collapse(first, {"--set", "scene.end_time=0.1"}), first / "log.txt").exit_status == 0);
  REQUIRE(run_child({SOILSPH_EXECUTABLE, "collapse", (first / "scene.toml").string(), "--threads", "1",
                     "--out", second.string()},
                    second / "log.txt")
              .exit_status == 0);
  CHECK(read_frames(second).last == read_frames(first).last);
}

namespace {

/// The axisymmetric column (a quarter) at 1 cm, 869 particles, to `end_time` without stopping at
/// rest (about 430 steps to 0.1 s), into `out`.
std::vector<std::string> column_3d(const fs::path& out, const std::string& end_time,
                                   std::vector<std::string> extra = {}) {
  std::vector<std::string> args{SOILSPH_EXECUTABLE,
                                "collapse",
                                SOILSPH_SOURCE_DIR "/data/scenes/axisymmetric-column.toml",
                                "--threads",
                                "1",
                                "--out",
                                out.string(),
                                "--set",
                                "scene.particle_spacing=0.01",
                                "--set",
                                "scene.stop_at_rest=false",
                                "--set",
                                "scene.end_time=" + end_time};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

/// The last frames of two runs agree in every bit, and so do the figures of their summaries (all
/// but the wall time and what follows from it, the command line and resumed_from). The resumed run
/// has every frame of the straight one, and one more if it was stopped by a signal (at the stop).
void check_same_run(const fs::path& resumed, const fs::path& straight, std::size_t stop_frames = 0) {
  const Frames a = read_frames(resumed, kSpaceSets), b = read_frames(straight, kSpaceSets);
  CHECK(std::includes(a.times.begin(), a.times.end(), b.times.begin(), b.times.end()));
  CHECK(a.times.size() <= b.times.size() + stop_frames);
  REQUIRE(a.last.size() == b.last.size());
  for (const auto& [name, values] : b.last) {
    INFO(name);
    CHECK(a.last.at(name) == values);  // exact: every bit
  }
  const std::string sa = text_of(resumed / "summary.json"), sb = text_of(straight / "summary.json");
  for (const char* key : {"steps", "end_time", "runout_radius_m", "runout_radius_spread_m", "height_m",
                          "smallest_time_step", "largest_time_step", "guard_corrections"}) {
    INFO(key);
    CHECK(json_number(sa, key) == json_number(sb, key));
  }
  CHECK_THAT(sa, Contains("\"complete\": true") && Contains("\"stop_reason\": \"end time\""));
}

}  // namespace

TEST_CASE("3D: a run stopped at its end time and resumed further ends bit for bit as one run",
          "[fault][resume][3d]") {
  const fs::path dir = fresh("resume-3d"), straight = fresh("resume-3d-straight");
  REQUIRE(run_child(column_3d(straight, "0.1"), straight / "log.txt").exit_status == 0);
  REQUIRE(run_child(column_3d(dir, "0.05"), dir / "log.txt").exit_status == 0);
  auto args = resume(dir);
  args.insert(args.end(), {"--set", "scene.end_time=0.1"});
  const auto resumed = run_child(args, dir / "resume-log.txt");
  INFO(resumed.log);
  REQUIRE(resumed.exit_status == 0);
  CHECK_THAT(resumed.log, Contains("resumed at t = 0.04"));  // the checkpoint before the end's short steps
  CHECK_THAT(text_of(dir / "summary.json"), !Contains("\"resumed_from\": null"));
  check_same_run(dir, straight);
}

TEST_CASE("3D: SIGTERM stops the run cleanly, and resumed it ends bit for bit as one that never stopped",
          "[fault][resume][3d]") {
  const fs::path dir = fresh("sigterm-3d"), straight = fresh("sigterm-3d-straight");
  const std::vector<std::string> often{"--set", "output.checkpoint_interval=0.01"};
  ChildOptions stop_early;
  stop_early.signal_when_exists = dir / "checkpoint.h5";
  stop_early.signal = SIGTERM;
  const auto stopped = run_child(column_3d(dir, "0.3", often), dir / "log.txt", stop_early);
  INFO(stopped.log);
  REQUIRE(stopped.exit_status == 143);
  CHECK_THAT(stopped.log, Contains("stopped by SIGTERM at t = ") && Contains("--resume " + dir.string()));
  CHECK_THAT(text_of(dir / "summary.json"),
             Contains("\"complete\": false") && Contains("\"stop_reason\": \"signal SIGTERM\""));
  const auto resumed = run_child(resume(dir), dir / "resume-log.txt");
  INFO(resumed.log);
  REQUIRE(resumed.exit_status == 0);
  REQUIRE(run_child(column_3d(straight, "0.3", often), straight / "log.txt").exit_status == 0);
  check_same_run(dir, straight, 1);
}

TEST_CASE(
    "3D: a soil that runs off the floor stops the run naming the floor's key, and the summary "
    "reports the steps and time it reached",
    "[fault][blow-up][3d]") {
  const fs::path dir = fresh("blow-up-3d");
  // The a = 1 column spreads to about 0.22 m (Lube et al. 2004): a floor of 0.12 m is too short.
  const auto r = run_child(column_3d(dir, "0.3", {"--set", "scene.floor_radius=0.12"}), dir / "log.txt");
  INFO(r.log);
  CHECK(r.exit_status == 1);
  CHECK_THAT(r.log, Contains("error: blow-up: ") && Contains("floor_radius") && Contains("(step "));
  CHECK_THAT(text_of(dir / "summary.json"), Contains("\"complete\": false") && Contains("blow-up") &&
                                                Contains("\"runout_radius_m\": null"));  // no deposit
  check_failed_summary(dir, r.log);
}

TEST_CASE("3D: a 3D checkpoint whose scene says 2D is refused, naming both dimensions", "[fault][resume][3d]") {
  const fs::path dir = fresh("resume-3d-dimension");
  REQUIRE(run_child(column_3d(dir, "0.05"), dir / "log.txt").exit_status == 0);
  {  // relabel the 3D checkpoint's scene as the 2D column's
    const hid_t file = H5Fopen((dir / "checkpoint.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    REQUIRE(H5Adelete(file, "scene") >= 0);
    const std::string scene = text_of(SOILSPH_SOURCE_DIR "/data/scenes/collapse-dp.toml");
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, scene.size());
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(file, "scene", type, space, H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(H5Awrite(attribute, type, scene.c_str()) >= 0);
    H5Aclose(attribute), H5Sclose(space), H5Tclose(type), H5Fclose(file);
  }
  const auto r = run_child(resume(dir), dir / "resume-log.txt");
  CHECK(r.exit_status != 0);
  CHECK_THAT(r.log, Contains("is the checkpoint of a 3D run, not of a 2D one"));
}
