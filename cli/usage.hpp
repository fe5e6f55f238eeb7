// Command-line usage errors of `stepdance`: the version flag and messages that name what is valid.
#pragma once

#include <CLI/CLI.hpp>

namespace stepdance::cli {

/// Adds `--version` (prints "stepdance <version>"). Context: main.
void add_version_flag(CLI::App& app);

/// A check for options naming a file or folder: an empty one (`--out ""`) is refused with
/// "--option: ... must not be empty" (exit kExitBadInput), never read as "not given".
const CLI::Validator& non_empty_path();

/// The same for options taking a number: `--duration ""` is refused, never read as "not given".
const CLI::Validator& non_empty_number();

/// Reports a parse error of `app` (help and --version print and return kExitOk). A first word
/// that is no command gets "unknown command 'x'; the commands are: sim, decode"; a missing one
/// gets the list too. Returns the exit status (kExitBadInput for errors).
int report_parse_error(CLI::App& app, const CLI::ParseError& error, int argc, char** argv);

}  // namespace stepdance::cli
