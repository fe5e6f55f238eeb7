// A command's help in one shape for `sim`, `decode` and `serve`: what it does, then its exit
// statuses (exit_codes.hpp); and the folder options every command that simulates takes.
#pragma once

#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

namespace stepdance::cli {

/// One exit status in a command's help: "3 an expectation failed", or with `or_code`
/// "130/143 interrupted by SIGINT/SIGTERM".
struct ExitStatusHelp {
  int code;
  const char* meaning;
  int or_code = -1;
};

/// Adds the subcommand `name`, described as `summary` followed, when `statuses` are given, by
/// " Exit status: 0 ok, 2 …, 4 …." Context: building the command line, before parsing.
CLI::App& add_command(CLI::App& app, const char* name, const std::string& summary,
                      std::initializer_list<ExitStatusHelp> statuses = {});

/// Adds --out, the folder a simulation writes its files into, its help prefixed by `scope` (""
/// or "simulation: "). Context: as add_command().
void add_output_folder_option(CLI::App& command, std::string& output_directory, const std::string& scope);
/// Adds --cache, the folder for compiled sketches, likewise.
void add_cache_folder_option(CLI::App& command, std::string& cache_directory, const std::string& scope);

}  // namespace stepdance::cli
