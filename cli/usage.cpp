// `stepdance` usage errors: --version, unknown or missing commands named with the valid ones.
#include "usage.hpp"

#include <iostream>
#include <string>

#include "exit_codes.hpp"

#ifndef STEPDANCE_VERSION
#define STEPDANCE_VERSION "unknown"
#endif

namespace stepdance::cli {
namespace {

/// "sim, decode" (every subcommand, in the order added).
std::string command_list(CLI::App& app) {
  std::string list;
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    list += (list.empty() ? "" : ", ") + command->get_name();
  }
  return list;
}

bool is_command(CLI::App& app, const std::string& word) {
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
    if (command->get_name() == word) return true;
  }
  return false;
}

}  // namespace

const CLI::Validator& non_empty_path() {
  static const CLI::Validator check(
      [](std::string& value) {
        return value.empty() ? std::string("must not be empty (it names a file or folder)") : std::string();
      },
      "PATH");
  return check;
}

const CLI::Validator& non_empty_number() {
  static const CLI::Validator check(
      [](std::string& value) {
        return value.empty() ? std::string("must not be empty (it takes a number)") : std::string();
      },
      "NUMBER");
  return check;
}

void add_version_flag(CLI::App& app) {
  app.set_version_flag("--version", std::string("stepdance ") + STEPDANCE_VERSION, "print the version and exit");
}

int report_parse_error(CLI::App& app, const CLI::ParseError& error, int argc, char** argv) {
  if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
    return app.exit(error) == 0 ? kExitOk : kExitBadInput;  // --help, --version
  }
  const std::string first = argc > 1 ? argv[1] : "";
  if (first.empty() || first[0] == '-') {
    if (first.empty()) {
      std::cerr << "stepdance: a command is needed: " << command_list(app) << " (stepdance --help)\n";
      return kExitBadInput;
    }
  } else if (!is_command(app, first)) {
    std::cerr << "stepdance: unknown command '" << first << "'; the commands are: " << command_list(app)
              << " (stepdance --help)\n";
    return kExitBadInput;
  }
  app.exit(error);
  return kExitBadInput;
}

}  // namespace stepdance::cli
