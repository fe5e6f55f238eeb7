// State shared by the section readers while one scenario file is read.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "scenario/scenario.hpp"
#include "scenario/table_reader.hpp"

namespace stepdance::sim::scenario {

/// The scenario being filled, where relative paths start, and where errors go.
struct ParseContext {
  Reporter& reporter;
  std::filesystem::path base_dir;
  Scenario& scenario;
  /// Whether duration_s was read successfully (times are checked against it only then).
  bool duration_valid = false;
  /// Every device name declared, including devices dropped for errors (no cascading reports).
  std::set<std::string, std::less<>> declared_devices;

  /// `path` made absolute against base_dir (absolute paths stay), normalized.
  std::string resolve(std::string_view path) const;
};

/// Calls `each` with every table of the array of tables `key` (written [[key]]); anything else
/// under that key is reported.
void for_each_table(TableReader& parent, std::string_view key, const std::function<void(const toml::table&)>& each);

/// Reads `key` as "board:A": an existing board and a port its module has (output or input side).
std::optional<PortRef> read_port(TableReader& reader, std::string_view key, bool output, ParseContext& context,
                                 Need need = Need::kRequired);

/// Parses "board:OUT_A" / "board:IN_A" (reported at `line` under `key` on failure).
std::optional<PortLineRef> parse_port_line(std::string_view text, std::string_view key, int line,
                                           ParseContext& context);

/// Reads `key` as a socket letter "A".."D".
std::optional<char> read_socket_letter(TableReader& reader, std::string_view key, Need need = Need::kOptional);

// The section readers, in the order the loader calls them (later ones refer to earlier ones).
void read_boards(TableReader& top, ParseContext& context);
/// [board.sd_card] of one board (read_boards calls it).
void read_sd_card(TableReader& board_reader, BoardConfig& board, ParseContext& context);
void read_machine(TableReader& top, ParseContext& context);
void read_devices(TableReader& top, ParseContext& context);
void read_cables(TableReader& top, ParseContext& context);
void read_timeline(TableReader& top, ParseContext& context);
void read_output(TableReader& top, ParseContext& context);
void read_hosts(TableReader& top, ParseContext& context);  // after read_output (transcripts)
void read_expectations(TableReader& top, ParseContext& context);

}  // namespace stepdance::sim::scenario
