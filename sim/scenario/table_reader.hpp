// Typed, error-reporting access to one TOML table; remembers which keys were read.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "scenario/diagnostic.hpp"
#include "scenario/value_range.hpp"

namespace stepdance::sim::scenario {

/// Collects the errors of one scenario file.
class Reporter {
 public:
  explicit Reporter(std::string file) : file_(std::move(file)) {}
  void error(int line, std::string message);
  bool has_errors() const { return !diagnostics_.empty(); }
  /// The errors, sorted by line (errors on one line keep the order they were found in).
  std::vector<Diagnostic> sorted() const;

 private:
  std::string file_;
  std::vector<Diagnostic> diagnostics_;
};

/// 1-based line where a node starts.
int line_of(const toml::node& node);

/// Whether a key is required.
enum class Need { kOptional, kRequired };

/// Reads one table. Every getter marks its key as known and reports a wrong type (returning
/// nothing); finish() reports the keys nobody asked for.
class TableReader {
 public:
  /// `what` names the table in messages, e.g. "[[board]]" or "the scenario".
  TableReader(const toml::table& table, std::string what, Reporter& reporter);

  const toml::table& table() const { return table_; }
  const std::string& what() const { return what_; }
  /// Line of the table itself (its header, or its opening brace).
  int line() const { return scenario::line_of(table_); }
  bool has(std::string_view key) const { return table_.contains(key); }
  /// Line of the key's value, or of the table when the key is absent.
  int line_of(std::string_view key) const;

  /// The raw node (marked known), or null if absent (reported if required).
  const toml::node* node(std::string_view key, Need need = Need::kOptional);
  std::optional<std::string> string(std::string_view key, Need need = Need::kOptional);
  std::optional<int64_t> integer(std::string_view key, Need need = Need::kOptional);
  /// Integers are accepted as numbers; nan and inf are reported.
  std::optional<double> number(std::string_view key, Need need = Need::kOptional);
  /// A number checked against its range (scenario/value_range.hpp); out of range is reported
  /// as "'key' must be in [low, high] unit, got value" and returns nothing.
  std::optional<double> number(std::string_view key, const NumberRange& range, Need need = Need::kOptional);
  std::optional<int64_t> integer(std::string_view key, const IntegerRange& range, Need need = Need::kOptional);
  std::optional<bool> boolean(std::string_view key, Need need = Need::kOptional);
  const toml::table* table(std::string_view key, Need need = Need::kOptional);
  const toml::array* array(std::string_view key, Need need = Need::kOptional);

  /// Marks a key as known without reading it.
  void accept(std::string_view key) { known_.insert(std::string(key)); }
  /// Reports `message` at the key's line.
  void error(std::string_view key, std::string message);
  /// Reports every key that no getter or accept() has touched as unknown.
  void finish();

  Reporter& reporter() { return reporter_; }

 private:
  void wrong_type(std::string_view key, const toml::node& value, std::string_view expected);

  const toml::table& table_;
  std::string what_;
  Reporter& reporter_;
  std::set<std::string, std::less<>> known_;
};

/// Reads `array` as exactly two numbers (integers accepted) into `out`; false if it is not.
bool read_number_pair(const toml::array& array, double (&out)[2]);

/// "a string", "an integer", … for a node's TOML type.
std::string_view type_phrase(const toml::node& node);

/// A number for a message: shortest form, e.g. "12.5", "10", "-0.25".
std::string format_number(double value);

}  // namespace stepdance::sim::scenario
