// `soilsph bench collapse [--out DIR] [--scenes A,B] [--set KEY=VALUE]...`: the SPH collapse's speed,
// as ratios to a bare SPH pair loop measured in the same run (sph/bench/bare_pair_loop.h): for each
// scene, particle-steps/s with one thread, two and auto, the time to rest and to the end time, the
// steps and time steps, and memory per particle. Writes DIR/bench_collapse.csv and .md.
#include <omp.h>
#include <sys/resource.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/soilsph/commands.h"
#include "sph/bench/bare_pair_loop.h"
#include "sph/collapse.h"

namespace soilsph::cli {

namespace {
struct BenchOptions {
  std::string out = "results/bench-collapse";
  std::string root = ".";
  std::vector<std::string> scenes{"collapse-dp", "collapse-mcc", "sphinxsys-column-collapse"};
  std::vector<std::string> overrides;
  double bare_seconds = 1.0;
};

struct Measurement {
  std::string scene, run;
  int threads;  ///< 0: auto
  sph::RunStatistics stats;
  sph::DepositMetrics deposit;
  double rate;  ///< soil particle-steps/s
  double bare_rate;
};

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

void run_bench(const BenchOptions& o) {
  using namespace soilsph::sph;
  std::filesystem::create_directories(o.out);
  const int cores = omp_get_num_procs();
  std::vector<Measurement> rows;
  std::ostringstream md;
  md << "| scene | run | threads | t end (s) | at rest | steps | Δt min–max (µs) | wall (s) | "
        "particle-steps/s "
        "| bare loop, 1 thread | ratio | runout (cm) | height (cm) | repose (°) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& name : o.scenes) {
    const std::string file = o.root + "/data/scenes/" + name + ".toml";
    std::vector<std::string> base = o.overrides;
    base.push_back("output.fields=[]");
    const Scene reference = load_scene(file, base);
    const Particles lattice = build_particles(reference);
    const std::span<const double> x(lattice.x.data(), lattice.soil_count),
        y(lattice.y.data(), lattice.soil_count);
    const double h = reference.geometry.smoothing_length();
    const double bare_before = bare_pair_loop_rate(x, y, h, o.bare_seconds);
    struct Variant {
      const char* run;
      int threads;
      bool to_end;
    };
    std::vector<Variant> variants{{"to rest", 1, false}};
    if (cores > 1) variants.push_back({"to rest", cores, false});
    variants.push_back({"to rest", 0, false});
    variants.push_back({"to end time", 0, true});
    std::vector<Measurement> scene_rows;
    for (const Variant& v : variants) {
      static const std::string kToEnd = "scene.stop_at_rest=false";
      std::vector<std::string> overrides = base;
      if (v.to_end) overrides.push_back(kToEnd);
      const Scene scene = load_scene(file, overrides);
      Collapse collapse(scene);
      const ThreadTuner tuner = v.threads == 0 ? ThreadTuner(cores, true) : ThreadTuner(v.threads, false);
      const RunStatistics stats = collapse.run(tuner);
      const double rate = static_cast<double>(collapse.particles().soil_count) *
                          static_cast<double>(stats.steps) / stats.wall_seconds;
      scene_rows.push_back({name, v.run, v.threads, stats, collapse.deposit(), rate, 0.0});
      std::printf("%s %s threads=%s: t=%.3f s, %zu steps, %.1f s wall, %.3g particle-steps/s\n", name.c_str(),
                  v.run, v.threads == 0 ? "auto" : std::to_string(v.threads).c_str(), stats.end_time,
                  stats.steps, stats.wall_seconds, rate);
      std::fflush(stdout);
    }
    const double bare_after = bare_pair_loop_rate(x, y, h, o.bare_seconds);
    const double bare = 0.5 * (bare_before + bare_after);
    std::printf(
        "%s: bare pair loop %.3g particle-steps/s (before %.3g, after %.3g); memory %.0f B/particle\n",
        name.c_str(), bare, bare_before, bare_after,
        static_cast<double>(lattice.bytes() + scene_rows.back().stats.workspace_bytes) /
            static_cast<double>(lattice.size()));
    for (Measurement& m : scene_rows) {
      m.bare_rate = bare;
      char line[512];
      std::snprintf(
          line, sizeof line,
          "| %s | %s | %s | %.3f | %s | %zu | %.1f–%.1f | %.1f | %.3g | %.3g | %.2f | %.2f | %.2f | %.1f |\n",
          m.scene.c_str(), m.run.c_str(), m.threads == 0 ? "auto" : std::to_string(m.threads).c_str(),
          m.stats.end_time, m.stats.stopped_at_rest ? "yes" : "no", m.stats.steps,
          1e6 * m.stats.smallest_time_step, 1e6 * m.stats.largest_time_step, m.stats.wall_seconds, m.rate,
          bare, m.rate / bare, 100 * m.deposit.runout_m, 100 * m.deposit.height_m,
          m.deposit.repose_angle_deg);
      md << line;
      rows.push_back(m);
    }
    md << "| " << name << " | memory | | | | | | | " << lattice.size() << " particles (soil + ghost) | "
       << static_cast<long>((lattice.bytes() + scene_rows.back().stats.workspace_bytes) / lattice.size())
       << " B/particle | | | | |\n";
  }
  std::ofstream csv(o.out + "/bench_collapse.csv");
  csv << "# soilsph bench collapse: SI units; rates in soil particle-steps/s; bare_rate: bare SPH pair loop, "
         "one "
         "thread, same run; threads 0 = auto\n"
         "scene,run,threads,end_time,stopped_at_rest,steps,smallest_time_step,largest_time_step,wall_seconds,"
         "particle_steps_per_second,bare_rate,ratio,runout_m,height_m,repose_angle_deg\n";
  for (const Measurement& m : rows)
    csv << m.scene << ',' << m.run << ',' << m.threads << ',' << m.stats.end_time << ','
        << (m.stats.stopped_at_rest ? 1 : 0) << ',' << m.stats.steps << ',' << m.stats.smallest_time_step
        << ',' << m.stats.largest_time_step << ',' << m.stats.wall_seconds << ',' << m.rate << ','
        << m.bare_rate << ',' << m.rate / m.bare_rate << ',' << m.deposit.runout_m << ','
        << m.deposit.height_m << ',' << m.deposit.repose_angle_deg << '\n';
  std::ofstream(o.out + "/bench_collapse.md") << md.str();
  std::printf("%speak memory %.0f MB; wrote %s/bench_collapse.csv and .md\n", md.str().c_str(),
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
  cmd->add_option("--root", o->root, "project root holding data/scenes/")->capture_default_str();
  cmd->add_option("--scenes", o->scenes, "scene names in data/scenes/")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--set", o->overrides,
                  "override a value of every scene, e.g. --set scene.particle_spacing=0.004")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("--bare-seconds", o->bare_seconds, "time spent on each bare-loop measurement")
      ->capture_default_str();
  cmd->callback([o] { run_bench(*o); });
}

}  // namespace soilsph::cli
