#pragma once
// Runs the soilsph executable as a child process for the fault tests: arguments, output to a log
// file, an optional file-size limit (RLIMIT_FSIZE, the disk-full case without root), a signal to
// send once a file appears, and the way it ended (exit status or signal).
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace soilsph::test {

struct ChildResult {
  int exit_status = -1;  ///< when it exited, else −1
  int signal = 0;        ///< when a signal ended it, else 0
  std::string log;       ///< stdout and stderr
};

struct ChildOptions {
  long file_size_limit = -1;                ///< bytes (RLIMIT_FSIZE), < 0: none
  std::filesystem::path signal_when_exists;  ///< send `signal` once this file exists ...
  int signal = 0;                            ///< ... (0: never)
  double timeout_seconds = 120;              ///< then SIGKILL, and the test fails on the log
};

inline ChildResult run_child(const std::vector<std::string>& args, const std::filesystem::path& log,
                             const ChildOptions& options = {}) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    if (options.file_size_limit >= 0) {
      const rlimit limit{static_cast<rlim_t>(options.file_size_limit), static_cast<rlim_t>(options.file_size_limit)};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    if (!freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), STDERR_FILENO) < 0) _exit(125);
    setenv("OMP_NUM_THREADS", "1", 1);
    execv(argv[0], argv.data());
    _exit(127);
  }
  const auto start = std::chrono::steady_clock::now();
  bool signalled = false;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (options.signal && !signalled && std::filesystem::exists(options.signal_when_exists)) {
      kill(pid, options.signal);
      signalled = true;
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::duration<double>(options.timeout_seconds)) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ChildResult r;
  if (WIFEXITED(status)) r.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  std::ifstream in(log);
  std::ostringstream text;
  text << in.rdbuf();
  r.log = text.str();
  return r;
}

}  // namespace soilsph::test
