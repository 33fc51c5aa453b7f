// `soilsph bench scaling [--scenes A,B] [--particles N,...] [--steps S] [--warm-up-steps W]
// [--threads T,...] [--rounds R]`: how the cost of a particle-step grows with the particle count.
// Each scene is refined to about each soil particle count by its spacing alone (soil particles ∝
// Δp^-dim), and S steps after its first W are timed with each thread count (W > 0 leaves out the
// run's start: the first neighbour search and the page faults of the buffers' first use, which at
// 10⁶ particles cost several steps and a run to rest pays once). Every size and thread count runs
// once per round, alternated, so that a machine whose speed drifts slows all alike, and each row
// reports the median over the rounds and the ratio of its rate to the smallest size's with the same
// threads in the same round (1 everywhere: a flat cost). Beside each size, the bare pair loop
// (sph/bench/bare_pair_loop.h) on the same soil points, one thread: the part of any drop that the
// lattice's own memory traffic explains. Writes DIR/scaling.csv and scaling.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <variant>

#include "apps/soilsph/bench_statistics.h"
#include "apps/soilsph/commands.h"
#include "apps/soilsph/data_dir.h"
#include "sph/bench/bare_pair_loop.h"
#include "sph/collapse.h"
#include "sph/collapse_3d.h"

namespace soilsph::cli {

namespace {
struct ScalingOptions {
  std::string out = "results/bench-scaling";
  std::string root;  ///< empty: the shipped data (data_dir())
  std::vector<std::string> scenes{"collapse-dp", "axisymmetric-column"};
  std::vector<std::string> overrides;
  std::vector<double> particles{1e4, 1e5, 1e6};
  int steps = 100;
  int warm_up_steps = 0;
  std::vector<int> threads{1, 2};
  int rounds = 1;
  double bare_seconds = 0.5;
};

/// A scene refined to about a soil particle count: the overrides that make it so and what they built.
struct SizedScene {
  std::string name, file;
  std::vector<std::string> overrides;  ///< --set, no output fields, then the spacing
  int dimension = 2;
  double spacing = 0.0;
  std::size_t soil = 0, ghosts = 0;
};

/// The scene's soil particle count, dimension and spacing as `overrides` build it.
struct Census {
  int dimension;
  double spacing;
  std::size_t soil, ghosts;
};

Census census(const std::string& file, const std::vector<std::string>& overrides) {
  const sph::AnyScene any = sph::load_any_scene(file, overrides);
  if (const auto* space = std::get_if<sph::Scene3>(&any)) {
    const sph::ParticlesOf<3> p = sph::build_particles_3d(*space);
    return {3, space->geometry.particle_spacing, p.soil_count, p.size() - p.soil_count};
  }
  const sph::Scene& plane = std::get<sph::Scene>(any);
  const sph::Particles p = sph::build_particles(plane);
  return {2, plane.geometry.particle_spacing, p.soil_count, p.size() - p.soil_count};
}

std::string spacing_override(double spacing) {
  char text[64];
  std::snprintf(text, sizeof text, "scene.particle_spacing=%.9g", spacing);
  return text;
}

/// The scene at the spacing Δp0 / m, m = (n / n0)^(1/dim), that gives about n soil particles, n0
/// being its count at its own spacing Δp0. A scene whose lattice must fit its shapes whole (the 2D
/// column's sides, the cylinder's radius: a whole number of spacings) refuses most such spacings;
/// then m is rounded to a multiple of 1/q, q falling from 100 to 1: Δp0 q / j with whole j fits
/// whatever Δp0 / ℓ fits when q is a multiple of ℓ, and m whole (q = 1) fits whatever Δp0 fitted.
SizedScene sized_scene(const ScalingOptions& o, const std::string& name, double particles) {
  const std::string root = o.root.empty() ? data_dir().string() : o.root;
  SizedScene s{.name = name, .file = root + "/data/scenes/" + name + ".toml", .overrides = o.overrides};
  s.overrides.push_back("output.fields=[]");
  const Census own = census(s.file, s.overrides);
  const double refinement = std::pow(particles / static_cast<double>(own.soil), 1.0 / own.dimension);
  s.overrides.push_back(spacing_override(own.spacing / refinement));
  for (const double q : {100.0, 40.0, 20.0, 10.0, 8.0, 5.0, 4.0, 2.0, 1.0}) {
    try {
      const Census sized = census(s.file, s.overrides);
      s.dimension = sized.dimension, s.spacing = sized.spacing, s.soil = sized.soil, s.ghosts = sized.ghosts;
      return s;
    } catch (const ParameterError&) {
      s.overrides.back() = spacing_override(own.spacing / (std::max(1.0, std::round(refinement * q)) / q));
    }
  }
  const Census sized = census(s.file, s.overrides);  // m whole; throws what the scene cannot take
  s.dimension = sized.dimension, s.spacing = sized.spacing, s.soil = sized.soil, s.ghosts = sized.ghosts;
  return s;
}

/// `steps` steps of a collapse after its first `warm_up`, with `threads` threads: wall seconds,
/// workspace bytes.
struct StepsRun {
  double wall_seconds;
  std::size_t workspace_bytes;
};

template <class Collapse, class Control>
StepsRun timed_steps(Collapse& collapse, Control control, int threads, int warm_up, int steps) {
  using Clock = std::chrono::steady_clock;
  const auto last = static_cast<std::size_t>(warm_up + steps);
  std::size_t done = 0;
  Clock::time_point start = Clock::now(), end = start;
  control.stop_requested = [&] { return done >= last; };
  const sph::RunStatistics stats = collapse.run(
      sph::ThreadTuner(threads, false), [](const auto&, double) {},
      [&](double, std::size_t n) {
        done = n;
        if (n == static_cast<std::size_t>(warm_up)) start = Clock::now();
        if (n == last) end = Clock::now();
      },
      control);
  if (stats.steps != last)
    throw std::runtime_error("bench scaling: " + std::to_string(stats.steps) + " steps run, not " +
                             std::to_string(last) + " (the scene ended first: raise its end_time)");
  return {std::chrono::duration<double>(end - start).count(), stats.workspace_bytes};
}

StepsRun run_timed_steps(const SizedScene& s, int threads, int warm_up, int steps) {
  std::vector<std::string> overrides = s.overrides;
  overrides.push_back("scene.stop_at_rest=false");
  const sph::AnyScene any = sph::load_any_scene(s.file, overrides);
  if (const auto* space = std::get_if<sph::Scene3>(&any)) {
    sph::Collapse3 collapse(*space);
    return timed_steps(collapse, sph::RunControlOf<3>{}, threads, warm_up, steps);
  }
  sph::Collapse collapse(std::get<sph::Scene>(any));
  return timed_steps(collapse, sph::RunControl{}, threads, warm_up, steps);
}

/// The bare pair loop's rate on the sized scene's soil points, one thread.
double bare_rate(const SizedScene& s, double seconds) {
  const sph::AnyScene any = sph::load_any_scene(s.file, s.overrides);
  const auto soil = [](const auto& p, int d) {
    const std::span<const double> axis = p.coordinates()[static_cast<std::size_t>(d)];
    return axis.first(p.soil_count);
  };
  if (const auto* space = std::get_if<sph::Scene3>(&any)) {
    const sph::ParticlesOf<3> p = sph::build_particles_3d(*space);
    return sph::bare_pair_loop_rate<3>({soil(p, 0), soil(p, 1), soil(p, 2)}, space->geometry.smoothing_length(),
                                       seconds);
  }
  const sph::Scene& plane = std::get<sph::Scene>(any);
  const sph::Particles p = sph::build_particles(plane);
  return sph::bare_pair_loop_rate<2>({soil(p, 0), soil(p, 1)}, plane.geometry.smoothing_length(), seconds);
}

/// One row: a sized scene with a thread count, every round's rate and its ratio to the smallest size.
struct Row {
  const SizedScene* scene;
  int threads;
  std::vector<double> walls{}, rates{}, ratios{};
  std::size_t workspace_bytes = 0;
  std::vector<double> bare_rates{}, bare_ratios{};  ///< the size's bare loop (one per round)
};

void write_tables(const ScalingOptions& o, const std::vector<Row>& rows) {
  std::ofstream csv(o.out + "/scaling.csv");
  csv << "# soilsph bench scaling: SI units; `steps` steps after the first `warm_up_steps` of each scene refined "
         "by its spacing; rates "
         "in soil particle-steps/s; ratio_to_smallest: the rate over the smallest size's with the same "
         "threads in the same round; bare_rate: bare SPH pair loop on the same soil points, one thread; "
         "rates, walls and ratios are medians over the rounds (runs alternated)\n"
         "scene,dimension,particle_spacing,soil_particles,ghost_particles,threads,steps,wall_seconds,"
         "particle_steps_per_second,ratio_to_smallest,bare_rate,bare_ratio_to_smallest,"
         "workspace_bytes_per_particle,rounds,warm_up_steps\n";
  std::string md =
      "| scene | soil particles | ghosts | threads | wall (s) | soil particle-steps/s | ratio to the smallest | "
      "bare loop | its ratio |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows) {
    const SizedScene& s = *r.scene;
    const double per_particle =
        static_cast<double>(r.workspace_bytes) / static_cast<double>(s.soil + s.ghosts);
    csv << s.name << ',' << s.dimension << ',' << s.spacing << ',' << s.soil << ',' << s.ghosts << ','
        << r.threads << ',' << o.steps << ',' << median(r.walls) << ',' << median(r.rates) << ','
        << median(r.ratios) << ',' << median(r.bare_rates) << ',' << median(r.bare_ratios) << ','
        << per_particle << ',' << o.rounds << ',' << o.warm_up_steps << '\n';
    char line[512];
    std::snprintf(line, sizeof line, "| %s | %zu | %zu | %d | %.1f | %.3g | %.2f | %.3g | %.2f |\n", s.name.c_str(),
                  s.soil, s.ghosts, r.threads, median(r.walls), median(r.rates), median(r.ratios),
                  median(r.bare_rates), median(r.bare_ratios));
    md += line;
  }
  std::ofstream(o.out + "/scaling.md") << md;
  std::printf("%swrote %s/scaling.csv and .md\n", md.c_str(), o.out.c_str());
}

void run_scaling(const ScalingOptions& o) {
  std::filesystem::create_directories(o.out);
  std::vector<SizedScene> sized;
  for (const std::string& name : o.scenes)
    for (double n : o.particles) {
      SizedScene s = sized_scene(o, name, n);
      const bool seen = std::any_of(sized.begin(), sized.end(),
                                    [&](const SizedScene& t) { return t.name == s.name && t.spacing == s.spacing; });
      if (!seen) sized.push_back(std::move(s));
    }
  std::vector<Row> rows;
  for (const SizedScene& s : sized)
    for (int t : o.threads) rows.push_back({.scene = &s, .threads = t});
  for (int round = 0; round < o.rounds; ++round) {
    std::vector<double> rates(rows.size()), bare(rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      Row& r = rows[k];
      const SizedScene& s = *r.scene;
      const StepsRun run = run_timed_steps(s, r.threads, o.warm_up_steps, o.steps);
      rates[k] = static_cast<double>(s.soil) * o.steps / run.wall_seconds;
      r.walls.push_back(run.wall_seconds), r.rates.push_back(rates[k]), r.workspace_bytes = run.workspace_bytes;
      bare[k] = k > 0 && rows[k - 1].scene == &s ? bare[k - 1] : bare_rate(s, o.bare_seconds);
      const std::string after = o.warm_up_steps > 0 ? " after " + std::to_string(o.warm_up_steps) : "";
      std::printf("%s, %zu soil + %zu ghosts, %d thread(s), round %d: %d steps%s in %.2f s, %.3g soil "
                  "particle-steps/s; bare loop %.3g\n",
                  s.name.c_str(), s.soil, s.ghosts, r.threads, round + 1, o.steps, after.c_str(), run.wall_seconds,
                  rates[k], bare[k]);
      std::fflush(stdout);
    }
    // The ratios to the smallest size of the same scene and threads, within this round.
    for (std::size_t k = 0; k < rows.size(); ++k) {
      std::size_t smallest = k;
      for (std::size_t m = 0; m < rows.size(); ++m)
        if (rows[m].scene->name == rows[k].scene->name && rows[m].threads == rows[k].threads &&
            rows[m].scene->soil < rows[smallest].scene->soil)
          smallest = m;
      rows[k].ratios.push_back(rates[k] / rates[smallest]);
      rows[k].bare_rates.push_back(bare[k]), rows[k].bare_ratios.push_back(bare[k] / bare[smallest]);
    }
  }
  write_tables(o, rows);
}
}  // namespace

void add_bench_scaling_command(CLI::App& bench) {
  auto* cmd = bench.add_subcommand(
      "scaling",
      "SPH cost per particle-step against the particle count: each scene refined to about each soil "
      "particle count, its steps timed with each thread count, beside the bare pair loop");
  auto o = std::make_shared<ScalingOptions>();
  cmd->add_option("--out", o->out, "output directory (scaling.csv, scaling.md)")->capture_default_str();
  cmd->add_option("--root", o->root, "folder holding data/scenes/ (default: the shipped data)");
  cmd->add_option("--scenes", o->scenes, "scene names in data/scenes/, 2D or 3D")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--set", o->overrides,
                  "override a value of every scene, e.g. --set numerics.velocity_gradient_correction=true")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("--particles", o->particles, "about this many soil particles per run, by the spacing alone")
      ->delimiter(',')
      ->check(CLI::Range(100.0, 1e8))
      ->capture_default_str();
  cmd->add_option("--steps", o->steps, "steps timed in each run, after the warm-up steps")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--warm-up-steps", o->warm_up_steps,
                  "steps run before the timed ones (0: the run's start, its first neighbour search and the "
                  "buffers' first touch, is timed too)")
      ->check(CLI::Range(0, 100000))
      ->capture_default_str();
  cmd->add_option("--threads", o->threads, "thread counts, each run at every size")
      ->delimiter(',')
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_option("--rounds", o->rounds, "runs of every size and thread count, alternated; rows report medians")
      ->check(CLI::Range(1, 99))
      ->capture_default_str();
  cmd->add_option("--bare-seconds", o->bare_seconds, "time spent on each bare-loop measurement")
      ->capture_default_str();
  cmd->callback([o] { run_scaling(*o); });
}

}  // namespace soilsph::cli
