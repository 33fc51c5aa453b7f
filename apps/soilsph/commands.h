#pragma once
/// @file
/// Each subcommand of `soilsph` lives in its own file and registers itself on the root app here.
/// A subcommand is thin: it parses options and calls the libraries.
#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

namespace soilsph::cli {

/// Thrown by a command to end the process with `code` after it has reported why (a run stopped by
/// a signal: 128 + the signal).
struct ExitCode {
  int code;
};

/// The command line this process was started with, words shell-quoted where needed (results record
/// it beside the version: summary.json, point CSV headers).
const std::string& invocation();

/// A word as a POSIX shell reads it back: bare if it holds only safe characters, else single-quoted.
std::string shell_quoted(const std::string& word);

void add_material_command(CLI::App& app);
void add_stress_test_command(CLI::App& app);
void add_bench_command(CLI::App& app);
/// `soilsph bench collapse`, registered by add_bench_command on the `bench` subcommand.
void add_bench_collapse_command(CLI::App& bench);
/// `soilsph bench scaling`, registered by add_bench_command on the `bench` subcommand.
void add_bench_scaling_command(CLI::App& bench);

void add_point_command(CLI::App& app);
void add_verify_command(CLI::App& app);
void add_collapse_command(CLI::App& app);
void add_calibrate_command(CLI::App& app);
void add_check_command(CLI::App& app);
void add_examples_command(CLI::App& app);

}  // namespace soilsph::cli
