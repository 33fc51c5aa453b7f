// `soilsph bench collapse [--out DIR] [--scenes A,B] [--set KEY=VALUE]... [--rounds N]`: the SPH
// collapse's speed, as ratios to a bare SPH pair loop measured in the same run
// (sph/bench/bare_pair_loop.h): for each scene, particle-steps/s with one thread, two and auto, the
// time to rest and to the end time, the steps and time steps, and memory per particle. With N rounds
// the runs of a scene alternate (every variant once per round, the bare loop between rounds), so that
// a machine whose speed drifts during the bench slows every variant alike, and each row reports the
// median. Writes DIR/bench_collapse.csv and .md. Then the bare pair loop on a square lattice and on
// a cubic one of about the same particle count (`--bare-particles`), alternated over the rounds:
// the 3D loop's rate beside the 2D one's, measured in the same process (DIR/bare_loops.csv).
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <span>

#include "apps/soilsph/bench_statistics.h"
#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"
#include "sph/bench/bare_pair_loop.h"
#include "sph/collapse.h"
#include "sph/collapse_3d.h"

namespace soilsph::cli {

namespace {
struct BenchOptions {
  std::string out = "results/bench-collapse";
  std::string root;  ///< empty: the shipped data (data_dir())
  std::vector<std::string> scenes{"collapse-dp", "collapse-mcc", "sphinxsys-column-collapse"};
  std::vector<std::string> overrides;
  double bare_seconds = 1.0;
  int rounds = 1;
  int bare_particles = 8000;  ///< about this many points in each of the 2D and 3D bare loops
};

struct Measurement {
  std::string scene, run;
  int threads;  ///< 0: auto
  sph::RunStatistics stats;
  sph::DepositMetrics deposit;
  double rate;  ///< soil particle-steps/s (median over the rounds)
  double bare_rate;
  double ratio;  ///< median over the rounds of rate / the bare loop's rate around that round
  double wall_min, wall_max;
};

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

/// One timed configuration of a scene's run.
struct Variant {
  const char* run;  ///< "to rest" or "to end time"
  int threads;      ///< 0: auto
  bool to_end;      ///< run to the end time rather than stop at rest
};

/// To rest with one thread, with every core (if more than one) and auto; to the end time with auto.
std::vector<Variant> variants_on(int cores) {
  std::vector<Variant> variants{{"to rest", 1, false}};
  if (cores > 1) variants.push_back({"to rest", cores, false});
  variants.push_back({"to rest", 0, false});
  variants.push_back({"to end time", 0, true});
  return variants;
}

/// A scene as the bench runs it (no frames written), of the plane or of space, and what its bare
/// loop runs on: the soil's lattice points in the scene's dimension.
struct BenchScene {
  std::string name, file;
  std::vector<std::string> overrides;  ///< --set, then no output fields
  int dimension = 2;
  std::array<std::vector<double>, 3> soil_points{};  ///< x, y[, z] of the soil at t = 0
  std::size_t particles = 0;                          ///< soil and ghosts
  std::size_t particle_bytes = 0;                     ///< of the particles' arrays
  double smoothing_length = 0.0;

  double bare_rate(double seconds) const {
    const auto& x = soil_points;
    return dimension == 2 ? sph::bare_pair_loop_rate<2>({x[0], x[1]}, smoothing_length, seconds)
                          : sph::bare_pair_loop_rate<3>({x[0], x[1], x[2]}, smoothing_length, seconds);
  }
  /// Bytes per particle (soil and ghost) of a run whose workspace took `workspace_bytes`.
  double bytes_per_particle(std::size_t workspace_bytes) const {
    return static_cast<double>(particle_bytes + workspace_bytes) / static_cast<double>(particles);
  }
};

/// Where a bench scene's bare loop runs and how large its particles are, from its built particles.
template <int dim>
void take_lattice(BenchScene& s, const sph::ParticlesOf<dim>& p, double smoothing_length) {
  s.dimension = dim;
  s.smoothing_length = smoothing_length;
  s.particles = p.size();
  s.particle_bytes = p.bytes();
  for (int d = 0; d < dim; ++d) {
    const std::span<const double> axis = p.coordinates()[static_cast<std::size_t>(d)];
    s.soil_points[static_cast<std::size_t>(d)].assign(axis.begin(), axis.begin() + static_cast<long>(p.soil_count));
  }
}

BenchScene bench_scene(const BenchOptions& o, const std::string& name) {
  const std::string root = o.root.empty() ? data_dir().string() : o.root;
  BenchScene s{.name = name, .file = root + "/data/scenes/" + name + ".toml", .overrides = o.overrides};
  s.overrides.push_back("output.fields=[]");
  const sph::AnyScene reference = sph::load_any_scene(s.file, s.overrides);
  if (const auto* space = std::get_if<sph::Scene3>(&reference))
    take_lattice(s, sph::build_particles_3d(*space), space->geometry.smoothing_length());
  else
    take_lattice(s, sph::build_particles(std::get<sph::Scene>(reference)),
                 std::get<sph::Scene>(reference).geometry.smoothing_length());
  return s;
}

/// One run of a variant: its statistics, deposit and soil particle-steps per second.
struct TimedRun {
  sph::RunStatistics stats;
  sph::DepositMetrics deposit;
  double rate;
};

/// The deposit columns of a 3D run: the slab's 2D measures; the axisymmetric column's (and a regions
/// scene's with [deposit]) runout radius, height on the axis and runout radius where a tenth of the
/// initial height thick as runout, height and thick runout (no repose angle).
sph::DepositMetrics deposit_of(const sph::Scene3& scene, const sph::Collapse3& collapse) {
  if (scene.geometry.shape == sph::Geometry3::Shape::Slab) return collapse.slab_deposit();
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (!scene.geometry.deposit_measured) return {.runout_m = none, .height_m = none, .repose_angle_deg = none, .runout_thick_m = none};
  const sph::AxisymmetricDeposit d = collapse.axisymmetric_deposit();
  return {.runout_m = d.runout_radius_m,
          .height_m = d.height_m,
          .repose_angle_deg = none,
          .runout_thick_m = d.runout_radius_thick_m};
}

TimedRun run_variant(const BenchScene& s, const Variant& v, int cores) {
  std::vector<std::string> overrides = s.overrides;
  if (v.to_end) overrides.push_back("scene.stop_at_rest=false");
  const sph::AnyScene any = sph::load_any_scene(s.file, overrides);
  const sph::ThreadTuner tuner =
      v.threads == 0 ? sph::ThreadTuner(cores, true) : sph::ThreadTuner(v.threads, false);
  const auto timed = [](auto& collapse, const sph::RunStatistics& stats, sph::DepositMetrics deposit) {
    const double rate = static_cast<double>(collapse.particles().soil_count) * static_cast<double>(stats.steps) /
                        stats.wall_seconds;
    return TimedRun{stats, deposit, rate};
  };
  if (const auto* space = std::get_if<sph::Scene3>(&any)) {
    sph::Collapse3 collapse(*space);
    const sph::RunStatistics stats = collapse.run(tuner);
    return timed(collapse, stats, deposit_of(*space, collapse));
  }
  sph::Collapse collapse(std::get<sph::Scene>(any));
  const sph::RunStatistics stats = collapse.run(tuner);
  return timed(collapse, stats, collapse.deposit());
}

std::string threads_label(int threads) {
  return threads == 0 ? "auto" : std::to_string(threads);
}

void print_run(const BenchScene& s, const Variant& v, int round, const TimedRun& r) {
  std::printf("%s %s threads=%s (round %d): t=%.3f s, %zu steps, %.1f s wall, %.3g particle-steps/s\n",
              s.name.c_str(), v.run, threads_label(v.threads).c_str(), round + 1, r.stats.end_time,
              r.stats.steps, r.stats.wall_seconds, r.rate);
  std::fflush(stdout);
}

/// What the rounds measured: per variant the first round's run and every round's wall time and rate;
/// the bare loop before the first round and after each.
struct Rounds {
  std::vector<TimedRun> first{};
  std::vector<std::vector<double>> walls, rates;
  std::vector<double> bare_rates;
};

/// Every variant once per round, the bare loop between rounds, so that a machine whose speed drifts
/// slows every variant alike.
Rounds run_rounds(const BenchScene& s, const std::vector<Variant>& variants, const BenchOptions& o,
                  int cores) {
  Rounds r{.walls = std::vector<std::vector<double>>(variants.size()),
           .rates = std::vector<std::vector<double>>(variants.size()),
           .bare_rates = {s.bare_rate(o.bare_seconds)}};
  for (int round = 0; round < o.rounds; ++round) {
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const TimedRun run = run_variant(s, variants[k], cores);
      if (round == 0) r.first.push_back(run);
      r.walls[k].push_back(run.stats.wall_seconds);
      r.rates[k].push_back(run.rate);
      print_run(s, variants[k], round, run);
    }
    r.bare_rates.push_back(s.bare_rate(o.bare_seconds));
  }
  return r;
}

/// The bare loop of round r is the mean of the measurements before and after it.
std::vector<double> bare_rate_per_round(const std::vector<double>& bare_rates) {
  std::vector<double> per_round;
  for (std::size_t round = 0; round + 1 < bare_rates.size(); ++round)
    per_round.push_back(0.5 * (bare_rates[round] + bare_rates[round + 1]));
  return per_round;
}

/// Each variant's row: the first round's run with the medians over the rounds of its wall time,
/// rate and ratio to the bare loop.
std::vector<Measurement> measurements(const BenchScene& s, const std::vector<Variant>& variants,
                                      const Rounds& r) {
  const std::vector<double> round_bare = bare_rate_per_round(r.bare_rates);
  const double bare = median(round_bare);
  std::vector<Measurement> rows;
  for (std::size_t k = 0; k < variants.size(); ++k) {
    std::vector<double> ratios;
    for (std::size_t round = 0; round < r.rates[k].size(); ++round)
      ratios.push_back(r.rates[k][round] / round_bare[round]);
    Measurement m{.scene = s.name,
                  .run = variants[k].run,
                  .threads = variants[k].threads,
                  .stats = r.first[k].stats,
                  .deposit = r.first[k].deposit,
                  .rate = median(r.rates[k]),
                  .bare_rate = bare,
                  .ratio = median(ratios),
                  .wall_min = *std::min_element(r.walls[k].begin(), r.walls[k].end()),
                  .wall_max = *std::max_element(r.walls[k].begin(), r.walls[k].end())};
    m.stats.wall_seconds = median(r.walls[k]);
    rows.push_back(m);
  }
  return rows;
}

void print_bare_loop(const BenchScene& s, const Rounds& r, const Measurement& last, int rounds) {
  std::string bare_list;
  for (double b : r.bare_rates)
    bare_list += (bare_list.empty() ? "" : ", ") + std::to_string(b / 1e6).substr(0, 4);
  std::printf(
      "%s: bare pair loop %.3g particle-steps/s (median of %d rounds; measured %se6); memory %.0f "
      "B/particle\n",
      s.name.c_str(), last.bare_rate, rounds, bare_list.c_str(),
      s.bytes_per_particle(last.stats.workspace_bytes));
}

constexpr const char* kMarkdownHeader =
    "| scene | run | threads | t end (s) | at rest | steps | Δt min–max (µs) | wall (s), median (min–max) | "
    "particle-steps/s | bare loop, 1 thread | ratio | runout (cm) | height (cm) | repose (°) |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";

/// A deposit measure in the table: "—" where it is not taken (NaN in the CSV), e.g. the repose angle
/// of an axisymmetric column.
std::string measure_cell(double value, const char* format) {
  if (!std::isfinite(value)) return "—";
  char cell[32];
  std::snprintf(cell, sizeof cell, format, value);
  return cell;
}

std::string markdown_row(const Measurement& m) {
  char line[512];
  std::snprintf(line, sizeof line,
                "| %s | %s | %s | %.3f | %s | %zu | %.1f–%.1f | %.1f (%.1f–%.1f) | %.3g | %.3g | %.2f | "
                "%s | %s | %s |\n",
                m.scene.c_str(), m.run.c_str(), threads_label(m.threads).c_str(), m.stats.end_time,
                m.stats.stopped_at_rest ? "yes" : "no", m.stats.steps, 1e6 * m.stats.smallest_time_step,
                1e6 * m.stats.largest_time_step, m.stats.wall_seconds, m.wall_min, m.wall_max, m.rate, m.bare_rate,
                m.ratio, measure_cell(100 * m.deposit.runout_m, "%.2f").c_str(),
                measure_cell(100 * m.deposit.height_m, "%.2f").c_str(),
                measure_cell(m.deposit.repose_angle_deg, "%.1f").c_str());
  return line;
}

std::string markdown_memory_row(const BenchScene& s, const Measurement& last) {
  return "| " + s.name + " | memory | | | | | | | " + std::to_string(s.particles) + " particles (soil + ghost) | " +
         std::to_string(static_cast<long>((s.particle_bytes + last.stats.workspace_bytes) / s.particles)) +
         " B/particle | | | | |\n";
}

void write_csv(const std::string& file, const std::vector<Measurement>& rows, int rounds) {
  std::ofstream csv(file);
  csv << "# soilsph bench collapse: SI units; rates in soil particle-steps/s; bare_rate: bare SPH pair loop, "
         "one thread, same run; threads 0 = auto; wall_seconds, particle_steps_per_second, bare_rate and "
         "ratio "
         "are medians over the rounds (runs alternated)\n"
         "scene,run,threads,end_time,stopped_at_rest,steps,smallest_time_step,largest_time_step,wall_seconds,"
         "particle_steps_per_second,bare_rate,ratio,runout_m,height_m,repose_angle_deg,rounds,wall_seconds_"
         "min,"
         "wall_seconds_max\n";
  for (const Measurement& m : rows)
    csv << m.scene << ',' << m.run << ',' << m.threads << ',' << m.stats.end_time << ','
        << (m.stats.stopped_at_rest ? 1 : 0) << ',' << m.stats.steps << ',' << m.stats.smallest_time_step
        << ',' << m.stats.largest_time_step << ',' << m.stats.wall_seconds << ',' << m.rate << ','
        << m.bare_rate << ',' << m.ratio << ',' << m.deposit.runout_m << ',' << m.deposit.height_m << ','
        << m.deposit.repose_angle_deg << ',' << rounds << ',' << m.wall_min << ',' << m.wall_max << '\n';
}

/// The points of a square (2D) or cubic (3D) lattice of spacing dx with `side` points per axis.
template <int dim>
std::array<std::vector<double>, dim> lattice_points(int side, double dx) {
  std::array<std::vector<double>, dim> x;
  const int nz = dim == 3 ? side : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const int c[3] = {i, j, k};
        for (int d = 0; d < dim; ++d) x[static_cast<std::size_t>(d)].push_back(c[d] * dx);
      }
  return x;
}

/// The bare pair loop in 2D and in 3D on lattices of about o.bare_particles points at h = 1.3Δp,
/// one thread, alternated over the rounds; prints the medians and writes DIR/bare_loops.csv.
void bare_loops_2d_and_3d(const BenchOptions& o) {
  using namespace soilsph::sph;
  const double dx = 1.0e-3, h = 1.3 * dx;
  const auto side2 = static_cast<int>(std::lround(std::sqrt(o.bare_particles)));
  const auto side3 = static_cast<int>(std::lround(std::cbrt(o.bare_particles)));
  const auto plane = lattice_points<2>(side2, dx);
  const auto space = lattice_points<3>(side3, dx);
  std::vector<double> rates2, rates3, ratios;
  for (int round = 0; round < o.rounds; ++round) {
    rates2.push_back(bare_pair_loop_rate<2>({plane[0], plane[1]}, h, o.bare_seconds));
    rates3.push_back(bare_pair_loop_rate<3>({space[0], space[1], space[2]}, h, o.bare_seconds));
    ratios.push_back(rates3.back() / rates2.back());
  }
  const double r2 = median(rates2), r3 = median(rates3), ratio = median(ratios);
  std::printf("bare pair loop, 1 thread, h = 1.3 dx: 2D %zu points %.3g particle-steps/s; 3D %zu points %.3g "
              "particle-steps/s; 3D/2D %.3f (median of %d rounds)\n",
              plane[0].size(), r2, space[0].size(), r3, ratio, o.rounds);
  std::ofstream csv(o.out + "/bare_loops.csv");
  csv << "# soilsph bench collapse: the bare SPH pair loop on a square and a cubic lattice, h = 1.3 dx, one "
         "thread, same run; rates in particle-steps/s, medians over the rounds\n"
         "dimension,particles,particle_steps_per_second,ratio_to_2d,rounds\n"
      << "2," << plane[0].size() << ',' << r2 << ",1," << o.rounds << '\n'
      << "3," << space[0].size() << ',' << r3 << ',' << ratio << ',' << o.rounds << '\n';
}

void run_bench(const BenchOptions& o) {
  std::filesystem::create_directories(o.out);
  const int cores = omp_get_num_procs();
  const std::vector<Variant> variants = variants_on(cores);
  std::vector<Measurement> rows;
  std::string md = kMarkdownHeader;
  for (const std::string& name : o.scenes) {
    const BenchScene scene = bench_scene(o, name);
    const Rounds rounds = run_rounds(scene, variants, o, cores);
    const std::vector<Measurement> scene_rows = measurements(scene, variants, rounds);
    print_bare_loop(scene, rounds, scene_rows.back(), o.rounds);
    for (const Measurement& m : scene_rows) md += markdown_row(m);
    md += markdown_memory_row(scene, scene_rows.back());
    rows.insert(rows.end(), scene_rows.begin(), scene_rows.end());
  }
  bare_loops_2d_and_3d(o);
  write_csv(o.out + "/bench_collapse.csv", rows, o.rounds);
  std::ofstream(o.out + "/bench_collapse.md") << md;
  std::printf("%speak memory %.0f MB; wrote %s/bench_collapse.csv and .md\n", md.c_str(),
              peak_rss_bytes() / 1e6, o.out.c_str());
}
}  // namespace

void add_bench_collapse_command(CLI::App& bench) {
  auto* cmd = bench.add_subcommand(
      "collapse",
      "SPH collapse speed: particle-steps/s with 1, 2 and auto threads, time to rest and to the end "
      "time, as ratios to a bare SPH pair loop timed in the same run");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("--out", o->out, "output directory (bench_collapse.csv, bench_collapse.md)")
      ->capture_default_str();
  cmd->add_option("--root", o->root, "folder holding data/scenes/ (default: the shipped data)");
  cmd->add_option("--scenes", o->scenes, "scene names in data/scenes/, 2D or 3D (e.g. axisymmetric-column)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--set", o->overrides,
                  "override a value of every scene, e.g. --set scene.particle_spacing=0.004")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("--bare-seconds", o->bare_seconds, "time spent on each bare-loop measurement")
      ->capture_default_str();
  cmd->add_option("--rounds", o->rounds,
                  "runs of every variant, alternated; each row reports the median (a drifting machine slows "
                  "all alike)")
      ->check(CLI::Range(1, 99))
      ->capture_default_str();
  cmd->add_option("--bare-particles", o->bare_particles,
                  "about this many points in each of the 2D and 3D bare loops run after the scenes")
      ->check(CLI::Range(64, 10000000))
      ->capture_default_str();
  cmd->callback([o] { run_bench(*o); });
}

}  // namespace soilsph::cli
