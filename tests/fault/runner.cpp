// The child process (fork + exec with limits and a wall-time kill) and the run of many cases.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "tests/fault/fuzz.h"

extern char** environ;

namespace soilsph::fuzz {

namespace {

/// The first `cap` bytes of a file (allocated by the file's size, not by the cap).
std::string read_capped(const fs::path& path, std::size_t cap = 1 << 20) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  std::ifstream in(path, std::ios::binary);
  if (ec || !in) return "";
  std::string text(static_cast<std::size_t>(std::min<std::uintmax_t>(size, cap)), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

std::string shell_quoted(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=.,/:@%") == std::string::npos;
  if (safe) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  if (!v || !*v) return fallback;
  char* end = nullptr;
  const unsigned long long x = std::strtoull(v, &end, 10);
  if (*end) throw std::invalid_argument(std::string(name) + "=" + v + ": expected a whole number");
  return x;
}

std::string outcome_words(const Outcome& o, double timeout) {
  switch (o.status) {
    case Outcome::Status::Exited:
      return "exit " + std::to_string(o.code);
    case Outcome::Status::Signalled:
      return "signal " + std::to_string(o.code) + " (" + strsignal(o.code) + ")";
    case Outcome::Status::Hang: {
      std::ostringstream s;
      s << "hang (killed after " << timeout << " s)";
      return s.str();
    }
    case Outcome::Status::NotStarted:
      return "not started";
  }
  return "?";
}

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\t' || c == '\r') c = ' ';
  if (s.size() > 400) s = s.substr(0, 400) + "...";
  return s;
}

const char* expect_words(Expect e) {
  switch (e) {
    case Expect::Any:
      return "0, 1 or 2";
    case Expect::InputError:
      return "2 (input error)";
    case Expect::Failure:
      return "1 or 2";
  }
  return "?";
}

}  // namespace

std::string last_line(const std::string& text) {
  std::size_t end = text.size();
  while (end > 0) {
    const std::size_t start = text.rfind('\n', end - 1);
    const std::size_t b = start == std::string::npos ? 0 : start + 1;
    const std::string line = text.substr(b, end - b);
    if (line.find_first_not_of(" \t\r") != std::string::npos) return line;
    if (start == std::string::npos) break;
    end = start;
  }
  return "";
}

Outcome run_child(const std::string& executable, const std::vector<std::string>& args, const fs::path& dir,
                  const Limits& limits) {
  Outcome o;
  // Everything the child needs is built before fork: between fork and exec only async-signal-safe
  // calls are made (the parent has other threads).
  std::vector<std::string> words = {executable};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_words;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "OMP_NUM_THREADS=", 16) != 0) env_words.emplace_back(*e);
  env_words.emplace_back("OMP_NUM_THREADS=1");
  std::vector<char*> envp;
  for (std::string& w : env_words) envp.push_back(w.data());
  envp.push_back(nullptr);
  const std::string dir_s = dir.string(), out_s = (dir / "stdout.txt").string(),
                    err_s = (dir / "stderr.txt").string();
  const rlimit address{limits.address_space_bytes, limits.address_space_bytes};
  const rlimit file_size{limits.file_size_bytes, limits.file_size_bytes};
  const rlimit no_core{0, 0};

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return o;
  if (pid == 0) {
    setpgid(0, 0);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    if (chdir(dir_s.c_str()) != 0) _exit(126);
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(out_s.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_s.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || out < 0 || err < 0) _exit(126);
    dup2(in, 0);
    dup2(out, 1);
    dup2(err, 2);
    if (limits.address_space_bytes) setrlimit(RLIMIT_AS, &address);
    if (limits.file_size_bytes) setrlimit(RLIMIT_FSIZE, &file_size);
    setrlimit(RLIMIT_CORE, &no_core);
    execve(argv[0], argv.data(), envp.data());
    _exit(127);
  }
  setpgid(pid, pid);  // also here, so that a kill of the group cannot race the child's own call
  int status = 0;
  bool hang = false;
  rusage usage{};
  for (int nap = 1;; nap = std::min(nap * 2, 20)) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > limits.timeout_seconds) {
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      hang = true;
      break;
    }
    ::usleep(static_cast<useconds_t>(nap) * 1000);
  }
  kill(-pid, SIGKILL);  // anything the child left behind in its group
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!hang) {
    o.cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  }
  if (hang) {
    o.status = Outcome::Status::Hang;
  } else if (WIFEXITED(status)) {
    o.status = Outcome::Status::Exited;
    o.code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    o.status = Outcome::Status::Signalled;
    o.code = WTERMSIG(status);
  }
  o.out =
      read_capped(dir / "stdout.txt", std::size_t{256} << 20);  // a point CSV of many rows is checked whole
  o.err = read_capped(dir / "stderr.txt");
  return o;
}

std::string command_line(const std::string& executable, const Case& c, const fs::path& dir) {
  std::string s = "cd " + shell_quoted(dir.string()) + " && " + shell_quoted(executable);
  for (const std::string& a : c.args) s += " " + shell_quoted(a);
  return s;
}

Config Config::from_environment(std::string executable, std::string source_dir, fs::path default_work_dir) {
  Config c;
  // A frozen copy for a long run, so that rebuilding meanwhile (an LTO link removes the executable
  // for minutes) cannot turn cases into exec failures.
  const char* frozen = std::getenv("SOILSPH_FUZZ_EXECUTABLE");
  c.executable = frozen && *frozen ? std::string(frozen) : std::move(executable);
  c.source_dir = std::move(source_dir);
  const char* dir = std::getenv("SOILSPH_FUZZ_DIR");
  c.work_dir = dir && *dir ? fs::path(dir) : default_work_dir;
  c.seed = env_number("SOILSPH_FUZZ_SEED", c.seed);
  c.first = env_number("SOILSPH_FUZZ_FIRST", c.first);
  c.count = env_number("SOILSPH_FUZZ_CASES", c.count);
  c.jobs = static_cast<int>(std::max<std::uint64_t>(1, env_number("SOILSPH_FUZZ_JOBS", 2)));
  c.keep_all = env_number("SOILSPH_FUZZ_KEEP", 0) != 0;
  c.verbose = env_number("SOILSPH_FUZZ_VERBOSE", 0) != 0;
  c.limits.timeout_seconds = static_cast<double>(env_number("SOILSPH_FUZZ_TIMEOUT", 20));
  c.limits.address_space_bytes = env_number("SOILSPH_FUZZ_MEMORY_MB", 4096) << 20;
  if (const char* only = std::getenv("SOILSPH_FUZZ_CASE"); only && *only) {
    std::stringstream s(only);
    for (std::string item; std::getline(s, item, ',');) c.only.push_back(std::stoull(item));
  }
  return c;
}

double measured_slowdown(const Config& config, const fs::path& dir) {
  const Inputs inputs = Inputs::load(config.source_dir);
  Case calibration;
  for (const Case& c : base_cases(inputs))
    if (c.command == "collapse") {
      calibration = c;
      break;
    }
  Limits generous = config.limits;
  generous.timeout_seconds = 600.0;
  std::vector<Outcome> outcomes(static_cast<std::size_t>(std::max(1, config.jobs)));
  std::vector<std::thread> copies;
  for (std::size_t k = 0; k < outcomes.size(); ++k) {
    const fs::path copy = dir / ("calibration-" + std::to_string(k));
    fs::remove_all(copy);
    fs::create_directories(copy);
    for (const File& f : calibration.files) std::ofstream(copy / f.name, std::ios::binary) << f.content;
    copies.emplace_back([&, k, copy] { outcomes[k] = run_child(config.executable, calibration.args, copy, generous); });
  }
  for (std::thread& t : copies) t.join();
  double slowdown = 1.0;
  for (const Outcome& o : outcomes)
    if (o.status == Outcome::Status::Exited && o.cpu_seconds > 0.0) slowdown = std::max(slowdown, o.seconds / o.cpu_seconds);
  return slowdown;
}

Limits calibrated_limits(Limits limits, double slowdown) {
  limits.timeout_seconds *= std::max(1.0, slowdown);
  return limits;
}

RunReport run(const Config& config) {
  const Inputs inputs = Inputs::load(config.source_dir);
  std::vector<std::uint64_t> indices = config.only;
  if (indices.empty())
    for (std::uint64_t k = 0; k < config.count; ++k) indices.push_back(config.first + k);
  // A run of chosen cases (a reproduction) keeps its folders apart from the last full run's.
  const fs::path failures_dir = config.work_dir / (config.only.empty() ? "failures" : "repro");
  const fs::path cases_dir = config.work_dir / "cases";
  fs::remove_all(failures_dir);
  fs::remove_all(cases_dir);
  fs::create_directories(failures_dir);
  fs::create_directories(cases_dir);

  RunReport report;
  // The time limit as on an idle machine, stretched by the load measured now (docs/method/fuzzing.md).
  report.slowdown = measured_slowdown(config, cases_dir);
  const Limits case_limits = calibrated_limits(config.limits, report.slowdown);
  report.timeout_seconds = case_limits.timeout_seconds;
  std::mutex mutex;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  const auto start = std::chrono::steady_clock::now();
  const auto worker = [&] {
    for (;;) {
      const std::size_t slot = next++;
      if (slot >= indices.size()) return;
      CaseResult r;
      r.c = make_case(inputs, config.seed, indices[slot]);
      char name[32];
      std::snprintf(name, sizeof name, "case-%06llu", static_cast<unsigned long long>(r.c.index));
      const fs::path dir = cases_dir / name;
      fs::remove_all(dir);
      fs::create_directories(dir);
      for (const File& f : r.c.files) {
        std::ofstream out(dir / f.name, std::ios::binary);
        out.write(f.content.data(), static_cast<std::streamsize>(f.content.size()));
      }
      // A run on more than one thread waits at every barrier for threads that share the (busy) cores
      // with the other jobs: it gets twice the time before it counts as a hang.
      Limits limits = case_limits;
      const auto threads = std::find(r.c.args.begin(), r.c.args.end(), "--threads");
      if (threads != r.c.args.end() && threads + 1 != r.c.args.end() && threads[1] != "1")
        limits.timeout_seconds *= 2;
      r.outcome = run_child(config.executable, r.c.args, dir, limits);
      r.findings = check(r.c, r.outcome, dir);
      if (r.outcome.status == Outcome::Status::Exited && r.outcome.code >= 0 && r.outcome.code <= 2) {
        const std::lock_guard lock(mutex);
        ++report.exit_counts[r.outcome.code];
      }
      const fs::path kept = failures_dir / name;
      if (!r.findings.empty()) {
        fs::remove_all(kept);
        fs::rename(dir, kept);
        // Frames are not needed to reproduce a case; summary.json and the logs are kept.
        std::error_code ec;
        for (const auto& e : fs::recursive_directory_iterator(kept, ec))
          if (e.is_regular_file() && e.file_size() > (8u << 20)) fs::remove(e.path(), ec);
        std::ofstream about(kept / "case.txt");
        about << "case " << r.c.index << " of seed " << r.c.seed << " (" << r.c.kind << ")\n"
              << "mutations: ";
        for (std::size_t k = 0; k < r.c.mutations.size(); ++k) about << (k ? "; " : "") << r.c.mutations[k];
        about << "\nexpected exit: " << expect_words(r.c.expect)
              << (r.c.expect_why.empty() ? "" : " (" + r.c.expect_why + ")") << "\n"
              << "outcome: " << outcome_words(r.outcome, case_limits.timeout_seconds) << " after "
              << r.outcome.seconds << " s\n"
              << "command: " << command_line(config.executable, r.c, kept) << "\n"
              << "reproduce: SOILSPH_FUZZ_SEED=" << r.c.seed << " SOILSPH_FUZZ_CASE=" << r.c.index
              << " test_input_fuzz '[input]'\n"
              << "last stderr line: " << last_line(r.outcome.err) << "\n";
        for (const Finding& f : r.findings) about << "finding: " << f.category << ": " << f.detail << "\n";
        std::ofstream repro(kept / "repro.sh");
        repro << "#!/bin/sh\n# case " << r.c.index << " of seed " << r.c.seed << "\n"
              << command_line(config.executable, r.c, kept) << "\necho \"exit status $?\"\n";
      } else if (config.keep_all) {
        fs::remove_all(kept);
        fs::rename(dir, kept);
      } else {
        fs::remove_all(dir);
      }
      const std::size_t finished = ++done;
      const std::lock_guard lock(mutex);
      if (config.verbose)
        std::cerr << "case " << r.c.index << " " << r.c.kind << ": "
                  << outcome_words(r.outcome, case_limits.timeout_seconds) << ", "
                  << (r.findings.empty() ? "ok" : r.findings.front().category) << "\n";
      else if (indices.size() >= 1000 && finished % (indices.size() / 20) == 0)
        std::cerr << "fuzz: " << finished << " of " << indices.size() << " cases, " << report.failures.size()
                  << " failing\n";
      if (!r.findings.empty()) {
        // The report needs stderr's last line, not a point run's CSV (kept in the case folder).
        r.outcome.out = last_line(r.outcome.out);
        r.outcome.out.shrink_to_fit();
        report.failures.push_back(std::move(r));
      }
    }
  };
  std::vector<std::thread> threads;
  for (int k = 0; k < std::max(1, config.jobs); ++k) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  report.cases = indices.size();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::sort(report.failures.begin(), report.failures.end(),
            [](const CaseResult& a, const CaseResult& b) { return a.c.index < b.c.index; });

  // By category: the count and the first case as an example.
  std::map<std::string, std::vector<const CaseResult*>> by_category;
  for (const CaseResult& r : report.failures) {
    std::vector<std::string> seen;
    for (const Finding& f : r.findings) {
      if (std::find(seen.begin(), seen.end(), f.category) != seen.end()) continue;
      seen.push_back(f.category);
      by_category[f.category].push_back(&r);
    }
  }
  std::ostringstream text;
  text << "soilsph input fuzzer: " << report.cases << " cases (seed " << config.seed << ", "
       << (config.only.empty() ? "cases " + std::to_string(config.first) + " to " +
                                     std::to_string(config.first + config.count - 1)
                               : std::string("chosen cases"))
       << ") in " << report.seconds << " s with " << config.jobs
       << " jobs; exit 0/1/2: " << report.exit_counts[0] << "/" << report.exit_counts[1] << "/"
       << report.exit_counts[2] << "; " << report.failures.size() << " failing case(s)\n"
       << "time limit " << report.timeout_seconds << " s per case: " << config.limits.timeout_seconds
       << " s on an idle machine times the load's slowdown " << report.slowdown
       << " (wall / CPU time of a calibration run)\n";
  for (const auto& [category, results] : by_category) {
    const CaseResult& r = *results.front();
    const Finding* f = &r.findings.front();
    for (const Finding& g : r.findings)
      if (g.category == category) f = &g;
    text << "  " << category << ": " << results.size() << " case(s), e.g. case " << r.c.index << " ("
         << r.c.mutations.front() << "): " << f->detail << "\n";
  }
  if (!report.failures.empty())
    text << "folders, commands and REPORT.md in " << failures_dir.string() << "\n";
  report.text = text.str();

  std::ofstream md(failures_dir / "REPORT.md");
  md << "# soilsph input fuzzer\n\n```\n" << report.text << "```\n\n";
  for (const auto& [category, results] : by_category) {
    md << "## " << category << " (" << results.size() << ")\n\n";
    for (const CaseResult* r : results) {
      char name[32];
      std::snprintf(name, sizeof name, "case-%06llu", static_cast<unsigned long long>(r->c.index));
      md << "- case " << r->c.index << " (" << r->c.kind << "): ";
      for (std::size_t k = 0; k < r->c.mutations.size(); ++k) md << (k ? "; " : "") << r->c.mutations[k];
      md << " — " << outcome_words(r->outcome, case_limits.timeout_seconds) << "\n";
      for (const Finding& f : r->findings)
        if (f.category == category) md << "  - " << one_line(f.detail) << "\n";
      md << "  - last stderr line: `" << one_line(last_line(r->outcome.err)) << "`\n";
      md << "  - `" << command_line(config.executable, r->c, failures_dir / name) << "`\n";
    }
    md << "\n";
  }
  std::ofstream tsv(failures_dir / "failures.tsv");
  tsv << "index\tkind\tcategories\toutcome\texpected\tmutations\tfindings\tlast_stderr_line\tcommand\n";
  for (const CaseResult& r : report.failures) {
    char name[32];
    std::snprintf(name, sizeof name, "case-%06llu", static_cast<unsigned long long>(r.c.index));
    std::string categories, details, mutations;
    for (const Finding& f : r.findings) {
      categories += (categories.empty() ? "" : ",") + f.category;
      details += (details.empty() ? "" : " | ") + f.detail;
    }
    for (const std::string& m : r.c.mutations) mutations += (mutations.empty() ? "" : "; ") + m;
    tsv << r.c.index << '\t' << r.c.kind << '\t' << categories << '\t'
        << outcome_words(r.outcome, case_limits.timeout_seconds) << '\t' << expect_words(r.c.expect) << '\t'
        << one_line(mutations) << '\t' << one_line(details) << '\t' << one_line(last_line(r.outcome.err))
        << '\t' << command_line(config.executable, r.c, failures_dir / name) << '\n';
  }
  fs::remove_all(cases_dir);
  return report;
}

}  // namespace soilsph::fuzz
