// TableReader and Reporter: typed key access, unknown-key detection and error collection.
#include "scenario/table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stepdance::sim::scenario {

void Reporter::error(int line, std::string message) {
  diagnostics_.push_back(Diagnostic{file_, line, std::move(message)});
}

std::vector<Diagnostic> Reporter::sorted() const {
  std::vector<Diagnostic> out = diagnostics_;
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) { return a.line < b.line; });
  return out;
}

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

std::string_view type_phrase(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    default: return "a date or time";
  }
}

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

TableReader::TableReader(const toml::table& table, std::string what, Reporter& reporter)
    : table_(table), what_(std::move(what)), reporter_(reporter) {}

int TableReader::line_of(std::string_view key) const {
  const toml::node* value = table_.get(key);
  return value != nullptr ? scenario::line_of(*value) : line();
}

const toml::node* TableReader::node(std::string_view key, Need need) {
  accept(key);
  const toml::node* value = table_.get(key);
  if (value == nullptr && need == Need::kRequired) {
    reporter_.error(line(), what_ + " is missing required key '" + std::string(key) + "'");
  }
  return value;
}

void TableReader::wrong_type(std::string_view key, const toml::node& value, std::string_view expected) {
  reporter_.error(scenario::line_of(value), "'" + std::string(key) + "' must be " + std::string(expected) + ", not " +
                                                std::string(type_phrase(value)));
}

std::optional<std::string> TableReader::string(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return std::nullopt;
  if (const auto* text = value->as_string()) return text->get();
  wrong_type(key, *value, "a string");
  return std::nullopt;
}

std::optional<int64_t> TableReader::integer(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return std::nullopt;
  if (const auto* whole = value->as_integer()) return whole->get();
  wrong_type(key, *value, "an integer");
  return std::nullopt;
}

std::optional<double> TableReader::number(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return std::nullopt;
  if (const auto* whole = value->as_integer()) return static_cast<double>(whole->get());
  if (const auto* real = value->as_floating_point()) {
    if (std::isfinite(real->get())) return real->get();
    reporter_.error(scenario::line_of(*value), "'" + std::string(key) + "' must be a finite number");
    return std::nullopt;
  }
  wrong_type(key, *value, "a number");
  return std::nullopt;
}

std::optional<double> TableReader::number(std::string_view key, const NumberRange& range, Need need) {
  const std::optional<double> value = number(key, need);
  if (!value || in_range(*value, range)) return value;
  error(key, out_of_range(key, range, *value));
  return std::nullopt;
}

std::optional<int64_t> TableReader::integer(std::string_view key, const IntegerRange& range, Need need) {
  const std::optional<int64_t> value = integer(key, need);
  if (!value || in_range(*value, range)) return value;
  error(key, out_of_range(key, range, *value));
  return std::nullopt;
}

std::optional<bool> TableReader::boolean(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return std::nullopt;
  if (const auto* flag = value->as_boolean()) return flag->get();
  wrong_type(key, *value, "true or false");
  return std::nullopt;
}

const toml::table* TableReader::table(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return nullptr;
  if (const auto* sub = value->as_table()) return sub;
  wrong_type(key, *value, "a table");
  return nullptr;
}

const toml::array* TableReader::array(std::string_view key, Need need) {
  const toml::node* value = node(key, need);
  if (value == nullptr) return nullptr;
  if (const auto* list = value->as_array()) return list;
  wrong_type(key, *value, "an array");
  return nullptr;
}

void TableReader::error(std::string_view key, std::string message) {
  reporter_.error(line_of(key), std::move(message));
}

void TableReader::finish() {
  for (const auto& [key, value] : table_) {
    if (known_.count(key.str()) == 0) {
      reporter_.error(static_cast<int>(key.source().begin.line),
                      "unknown key '" + std::string(key.str()) + "' in " + what_);
    }
  }
}

bool read_number_pair(const toml::array& array, double (&out)[2]) {
  if (array.size() != 2) return false;
  for (size_t i = 0; i < 2; ++i) {
    const toml::node& item = *array.get(i);
    if (const auto* whole = item.as_integer()) {
      out[i] = static_cast<double>(whole->get());
    } else if (const auto* real = item.as_floating_point()) {
      out[i] = real->get();
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace stepdance::sim::scenario
