// [[device]]: the keys every device has (name, type, board, connector), then its kind's own keys,
// read by the kind's row (kinds/device_registry.hpp).
#include <map>
#include <set>
#include <string_view>
#include <tuple>
#include <utility>

#include "kinds/device_registry.hpp"
#include "scenario/file_names.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

struct DeviceNames {
  std::map<std::string, int> first_lines;
  /// (board, connector) → device using it.
  std::map<std::pair<std::string, Connector>, std::string> connectors;
  /// (board, QWIIC connector, I2C address) → device using it.
  std::map<std::tuple<std::string, Connector, int>, std::string> i2c_addresses;
};

/// Keys of other kinds that this kind does not have: each reported once, in the registry's order.
void report_foreign_keys(TableReader& reader, const DeviceKind& kind) {
  std::set<std::string_view> reported;
  for (const DeviceKind* other : device_kinds()) {
    for (const DeviceKey& key : other->keys) {
      if (kind.has_key(key.name) || !reader.has(key.name) || !reported.insert(key.name).second) continue;
      reader.accept(key.name);
      reader.error(key.name, "'" + std::string(key.name) + "' does not apply to " + std::string(kind.with_article));
    }
  }
}

/// Claims (board, connector) for the device; false (reported at `key`) if another device has it.
bool claim(TableReader& reader, std::string_view key, const std::string& text, const BoardConfig& board,
           Connector connector, const std::string& device, DeviceNames& names) {
  const auto slot = std::make_pair(board.name, connector);
  if (const auto user = names.connectors.find(slot); user != names.connectors.end()) {
    reader.error(
        key, "connector " + text + " of board '" + board.name + "' is already used by device '" + user->second + "'");
    return false;
  }
  names.connectors.emplace(slot, device);
  return true;
}

/// name: non-empty, a file name, unique. False if it is not.
bool read_name(TableReader& reader, DeviceConfig& device, ParseContext& context, DeviceNames& names) {
  const auto name = reader.string("name", Need::kRequired);
  if (!name) return false;
  if (name->empty()) {
    reader.error("name", "device name must not be empty");
  } else if (const std::string problem = file_name_problem(*name); !problem.empty()) {
    reader.error("name",
                 "device name \"" + *name + "\" names the device's files in the output folder, so it " + problem);
  } else if (const auto first = names.first_lines.find(*name); first != names.first_lines.end()) {
    reader.error("name",
                 "duplicate device name '" + *name + "' (first defined on line " + std::to_string(first->second) + ")");
  } else {
    names.first_lines[*name] = reader.line_of("name");
    context.declared_devices.insert(*name);
    device.name = *name;
    return true;
  }
  return false;
}

/// type: a registered kind.
const DeviceKind* read_kind(TableReader& reader) {
  const std::optional<std::string> text = reader.string("type", Need::kRequired);
  if (!text) return nullptr;
  const DeviceKind* kind = find_device_kind(*text);
  if (kind == nullptr) reader.error("type", "'type' must be " + device_kind_names() + ", got \"" + *text + "\"");
  return kind;
}

/// connector: one the kind fits, the board has and no other device uses (a QWIIC bus is shared,
/// by address).
void read_connector(TableReader& reader, DeviceConfig& device, const DeviceKind* kind, const BoardConfig* board,
                    DeviceNames& names) {
  const auto text = reader.string("connector", Need::kRequired);
  if (!text) return;
  const std::optional<Connector> connector = parse_connector(*text);
  if (!connector) {
    reader.error("connector", "unknown connector '" + *text +
                                  "' (connectors are ENC1, ENC2, A1..A4, D1, D2, LIMIT_A..LIMIT_D, QWIIC0 and QWIIC1)");
  } else if (kind != nullptr && !kind->fits(*connector)) {
    reader.error("connector", std::string(kind->with_article) + " cannot use connector " + *text + " (use " +
                                  std::string(kind->connectors) + ")");
  } else if (board != nullptr && !module_has_connector(*board->module, *connector)) {
    reader.error("connector", "board '" + board->name + "' (" + std::string(module_name(*board->module)) +
                                  " module) has no connector " + *text);
  } else if (board != nullptr) {
    if (!is_qwiic_connector(*connector)) claim(reader, "connector", *text, *board, *connector, device.name, names);
    device.connector = *connector;
  }
}

/// The device's I2C address is its own on its bus.
void check_i2c_address(TableReader& reader, const DeviceConfig& device, const BoardConfig* board, DeviceNames& names) {
  if (device.i2c_address < 0 || board == nullptr) return;
  const auto key = std::make_tuple(board->name, device.connector, device.i2c_address);
  if (const auto user = names.i2c_addresses.find(key); user != names.i2c_addresses.end()) {
    reader.error(reader.has("address") ? "address" : "connector",
                 "address " + std::to_string(device.i2c_address) + " on " +
                     std::string(connector_name(device.connector)) + " of board '" + board->name +
                     "' is already used by device '" + user->second + "'");
  } else {
    names.i2c_addresses.emplace(key, device.name);
  }
}

void read_device(const toml::table& table, ParseContext& context, DeviceNames& names) {
  TableReader reader(table, "[[device]]", context.reporter);
  DeviceConfig device;
  device.line = reader.line();
  const bool named = read_name(reader, device, context, names);
  const DeviceKind* kind = read_kind(reader);
  const BoardConfig* board = nullptr;
  if (const auto board_name = reader.string("board", Need::kRequired)) {
    board = context.scenario.board(*board_name);
    if (board == nullptr) {
      reader.error("board", "unknown board '" + *board_name + "'");
    } else {
      device.board = *board_name;
    }
  }
  read_connector(reader, device, kind, board, names);
  if (kind == nullptr) return;  // the kind's keys cannot be judged
  device.kind = kind;
  report_foreign_keys(reader, *kind);
  DeviceReading reading{reader, context, device, [&](std::string_view key, Connector connector) {
                          const std::string text(connector_name(connector));
                          return board != nullptr && claim(reader, key, text, *board, connector, device.name, names);
                        }};
  device.settings = kind->read(reading);
  check_i2c_address(reader, device, board, names);
  reader.finish();
  if (named) context.scenario.devices.push_back(std::move(device));
}

}  // namespace

void read_devices(TableReader& top, ParseContext& context) {
  DeviceNames names;
  for_each_table(top, "device", [&](const toml::table& table) { read_device(table, context, names); });
}

}  // namespace stepdance::sim::scenario
