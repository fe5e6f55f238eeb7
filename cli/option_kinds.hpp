// The kinds of option the commands share: a file or folder, and a number kept as text for the
// one number parser (scenario/value_range.hpp), which reads it later and says what is wrong.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "scenario/value_range.hpp"

namespace stepdance::cli {

/// Adds an option naming a file or folder; an empty one is refused (non_empty_path()).
CLI::Option* add_path_option(CLI::App& command, const std::string& name, std::string& path, const std::string& help);

/// Adds an option taking a number, kept as text; an empty one is refused (non_empty_number()).
CLI::Option* add_number_option(CLI::App& command, const std::string& name, std::string& number,
                               const std::string& help);

/// `text` read by parse_number_option(); empty (the message on stderr) when it is not in `range`.
std::optional<double> read_number_option(const char* option, const std::string& text,
                                         const sim::scenario::NumberRange& range);

/// The same for a whole number (parse_integer_option()).
std::optional<int64_t> read_integer_option(const char* option, const std::string& text,
                                           const sim::scenario::IntegerRange& range);

}  // namespace stepdance::cli
