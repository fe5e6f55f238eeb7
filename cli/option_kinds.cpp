// Path and number options: the check that refuses an empty value, and the number read with its message.
#include "option_kinds.hpp"

#include <iostream>

#include "usage.hpp"

namespace stepdance::cli {
namespace {

/// `number` as the parser gave it, its message on stderr when it refused the text.
template <typename Number>
std::optional<Number> reported(std::optional<Number> number, const std::string& error) {
  if (!number) std::cerr << error << "\n";
  return number;
}

}  // namespace

CLI::Option* add_path_option(CLI::App& command, const std::string& name, std::string& path, const std::string& help) {
  return command.add_option(name, path, help)->check(non_empty_path());
}

CLI::Option* add_number_option(CLI::App& command, const std::string& name, std::string& number,
                               const std::string& help) {
  return command.add_option(name, number, help)->check(non_empty_number());
}

std::optional<double> read_number_option(const char* option, const std::string& text,
                                         const sim::scenario::NumberRange& range) {
  std::string error;
  return reported(sim::scenario::parse_number_option(option, text, range, error), error);
}

std::optional<int64_t> read_integer_option(const char* option, const std::string& text,
                                           const sim::scenario::IntegerRange& range) {
  std::string error;
  return reported(sim::scenario::parse_integer_option(option, text, range, error), error);
}

}  // namespace stepdance::cli
