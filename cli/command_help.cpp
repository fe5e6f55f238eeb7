// add_command: a subcommand with its summary and exit statuses; the simulation folder options.
#include "command_help.hpp"

#include "option_kinds.hpp"

namespace stepdance::cli {

CLI::App& add_command(CLI::App& app, const char* name, const std::string& summary,
                      std::initializer_list<ExitStatusHelp> statuses) {
  std::string description = summary;
  const char* separator = " Exit status: ";
  for (const ExitStatusHelp& status : statuses) {
    description += separator + std::to_string(status.code);
    if (status.or_code >= 0) description += "/" + std::to_string(status.or_code);
    description += std::string(" ") + status.meaning;
    separator = ", ";
  }
  if (statuses.size() > 0) description += ".";
  return *app.add_subcommand(name, description);
}

void add_output_folder_option(CLI::App& command, std::string& output_directory, const std::string& scope) {
  add_path_option(command, "--out", output_directory, scope + "write the output files into this folder instead");
}

void add_cache_folder_option(CLI::App& command, std::string& cache_directory, const std::string& scope) {
  add_path_option(command, "--cache", cache_directory,
                  scope +
                      "folder for compiled sketches (default: $STEPDANCE_SKETCH_CACHE, else "
                      "~/.cache/stepdance/sketches)");
}

}  // namespace stepdance::cli
