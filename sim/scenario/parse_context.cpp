// Shared helpers of the section readers: paths, arrays of tables, port and socket references.
#include "scenario/parse_context.hpp"

#include "scenario/names.hpp"

namespace stepdance::sim::scenario {

std::string ParseContext::resolve(std::string_view path) const {
  const std::filesystem::path given{std::string(path)};
  const std::filesystem::path full = given.is_absolute() ? given : base_dir / given;
  return full.lexically_normal().string();
}

void for_each_table(TableReader& parent, std::string_view key, const std::function<void(const toml::table&)>& each) {
  const toml::node* node = parent.node(key);
  if (node == nullptr) return;
  const std::string shape = "'" + std::string(key) + "' must be written as [[" + std::string(key) + "]] tables";
  const toml::array* list = node->as_array();
  if (list == nullptr) {
    parent.reporter().error(line_of(*node), shape);
    return;
  }
  for (const toml::node& element : *list) {
    if (const toml::table* table = element.as_table()) {
      each(*table);
    } else {
      parent.reporter().error(line_of(element), shape);
    }
  }
}

std::optional<PortRef> read_port(TableReader& reader, std::string_view key, bool output, ParseContext& context,
                                 Need need) {
  const std::optional<std::string> text = reader.string(key, need);
  if (!text) return std::nullopt;
  const std::optional<SplitRef> split = split_ref(*text);
  if (!split || split->rest.size() != 1) {
    reader.error(key, "'" + std::string(key) + "' must look like \"board:A\", got \"" + *text + "\"");
    return std::nullopt;
  }
  const BoardConfig* board = context.scenario.board(split->board);
  if (board == nullptr) {
    reader.error(key, "unknown board '" + split->board + "'");
    return std::nullopt;
  }
  const char port = split->rest[0];
  if (!(output ? module_has_output_port(*board->module, port) : module_has_input_port(*board->module, port))) {
    reader.error(key, "board '" + board->name + "' (" + std::string(module_name(*board->module)) + " module) has no " +
                          (output ? "output" : "input") + " port " + split->rest);
    return std::nullopt;
  }
  return PortRef{board->name, port};
}

std::optional<PortLineRef> parse_port_line(std::string_view text, std::string_view key, int line,
                                           ParseContext& context) {
  const std::optional<SplitRef> split = split_ref(text);
  const bool out_form = split && split->rest.size() == 5 && split->rest.compare(0, 4, "OUT_") == 0;
  const bool in_form = split && split->rest.size() == 4 && split->rest.compare(0, 3, "IN_") == 0;
  if (!out_form && !in_form) {
    context.reporter.error(line, "'" + std::string(key) + "' must look like \"board:OUT_A\" or \"board:IN_A\", got \"" +
                                     std::string(text) + "\"");
    return std::nullopt;
  }
  const BoardConfig* board = context.scenario.board(split->board);
  if (board == nullptr) {
    context.reporter.error(line, "unknown board '" + split->board + "'");
    return std::nullopt;
  }
  const char port = split->rest.back();
  if (!(out_form ? module_has_output_port(*board->module, port) : module_has_input_port(*board->module, port))) {
    context.reporter.error(line, "board '" + board->name + "' (" + std::string(module_name(*board->module)) +
                                     " module) has no " + (out_form ? "output" : "input") + " port " + port);
    return std::nullopt;
  }
  return PortLineRef{board->name, out_form, port};
}

std::optional<char> read_socket_letter(TableReader& reader, std::string_view key, Need need) {
  const std::optional<std::string> text = reader.string(key, need);
  if (!text) return std::nullopt;
  if (text->size() != 1 || (*text)[0] < 'A' || (*text)[0] > 'D') {
    reader.error(key, "'" + std::string(key) + "' must be a socket letter A..D, got \"" + *text + "\"");
    return std::nullopt;
  }
  return (*text)[0];
}

}  // namespace stepdance::sim::scenario
