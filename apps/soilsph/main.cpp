// soilsph: constitutive-model verification and SPH soil-collapse simulation.
#include <cerrno>
#include <csignal>
#include <cstring>
#include <iostream>
#include <ranges>
#include <vector>

#include "apps/soilsph/commands.h"
#include "constitutive/parameters.h"
#include "soilsph/version.h"

namespace soilsph::cli {
namespace {
std::string g_invocation;

/// The commands `soilsph --help` lists, in its groups: adding a command is adding its line here.
struct CommandGroup {
  const char* title;
  std::vector<void (*)(CLI::App&)> add;
};
const CommandGroup kCommandGroups[] = {
    {"Commands",
     {add_examples_command, add_collapse_command, add_check_command, add_point_command, add_material_command,
      add_verify_command, add_calibrate_command}},
    {"Developer commands", {add_stress_test_command, add_bench_command}},
};

void add_commands(CLI::App& app) {
  for (const CommandGroup& group : kCommandGroups)
    for (const auto add : group.add) {
      const std::size_t before = app.get_subcommands({}).size();
      add(app);
      for (CLI::App* command : app.get_subcommands({}) | std::views::drop(before))
        command->group(group.title);
    }
}
}  // namespace

std::string shell_quoted(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                           "0123456789_-+=.,/:@%") == std::string::npos;
  if (safe) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

const std::string& invocation() { return g_invocation; }

/// A message as one readable line: a value quoted from the input may be 100 000 characters long.
std::string one_line(std::string message) {
  constexpr std::size_t kMost = 1000;
  for (char& c : message) c = c == '\n' ? ' ' : c;
  if (message.size() <= kMost) return message;
  return message.substr(0, kMost - 200) + " […" + std::to_string(message.size() - kMost + 100) + " characters cut…] " +
         message.substr(message.size() - 100);
}
/// Where a bad command line is explained: the help of the deepest command it named (`soilsph
/// bench point --help`), or the top-level help when it named none.
std::string help_hint(const CLI::App& app) {
  std::string command = "soilsph";
  for (const CLI::App* at = &app; !at->get_subcommands().empty();) {
    at = at->get_subcommands().front();
    command += " " + at->get_name();
  }
  return command == "soilsph" ? "soilsph --help lists the commands and options"
                              : command + " --help lists its options";
}
}  // namespace soilsph::cli

using soilsph::cli::one_line;

int main(int argc, char** argv) {
  for (int i = 0; i < argc; ++i)
    soilsph::cli::g_invocation += (i ? " " : "") + soilsph::cli::shell_quoted(i ? argv[i] : "soilsph");
  // Named here, so that the usage line says `soilsph` wherever the executable lies.
  CLI::App app{"soilsph: elastic-plastic soil models (Drucker-Prager, Modified Cam-Clay, Mohr-Coulomb), "
               "their material-point verification, and SPH soil-collapse simulation",
               "soilsph"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("soilsph ") + soilsph::kVersion);
  soilsph::cli::add_commands(app);
  app.footer("Start with `soilsph examples`; `soilsph COMMAND --help` describes each command.");
  // A closed pipe is a write error reported below, not a silent death by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  // Past a file-size limit (ulimit -f) a write fails with EFBIG and is reported, instead of SIGXFSZ
  // killing the process with a half-written file.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    app.parse(argc, argv);
    // Results written to standard output (point CSVs, reports) are lost if it is full or closed:
    // that is a failure, never an exit 0.
    errno = 0;
    std::cout.flush();
    if (!std::cout) {
      std::cerr << "error: cannot write to standard output"
                << (errno ? std::string(": ") + std::strerror(errno) : std::string()) << '\n';
      return 1;
    }
  } catch (const soilsph::cli::ExitCode& e) {
    return e.code;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help and --version
    // A bad command line is an input error: one `error:` line like every other, exit 2.
    std::cerr << one_line("error: " + std::string(e.what()) + " (" + soilsph::cli::help_hint(app) + ")")
              << '\n';
    return 2;
  } catch (const soilsph::ParameterError& e) {
    std::cerr << one_line(std::string("error: ") + e.what()) << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << one_line(std::string("error: ") + e.what()) << '\n';
    return 1;
  }
  return 0;
}
