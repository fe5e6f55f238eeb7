// [[device]]: encoders, potentiometers, buttons, limit switches and pendulums on board connectors.
#include <cmath>
#include <map>
#include <tuple>
#include <set>
#include <string_view>
#include <utility>

#include "scenario/file_names.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Keys and the device types they belong to (a key may belong to several).
constexpr std::pair<const char*, DeviceType> kTypeKeys[] = {
    {"pulses_per_revolution", DeviceType::kEncoder}, {"start_count", DeviceType::kEncoder},
    {"pulses_per_revolution", DeviceType::kPendulum}, {"amplitude_deg", DeviceType::kPendulum},
    {"period_s", DeviceType::kPendulum},             {"decay_s", DeviceType::kPendulum},
    {"release_s", DeviceType::kPendulum},
    {"pulses_per_revolution", DeviceType::kFiveBarArm}, {"left_connector", DeviceType::kFiveBarArm},
    {"path_mm", DeviceType::kFiveBarArm},              {"speed_mm_per_s", DeviceType::kFiveBarArm},
    {"start_s", DeviceType::kFiveBarArm},              {"right_min_deg", DeviceType::kFiveBarArm},
    {"left_max_deg", DeviceType::kFiveBarArm},
    {"position", DeviceType::kPotentiometer},        {"bounce_ms", DeviceType::kButton},
    {"pressed_level", DeviceType::kButton},          {"axis", DeviceType::kLimitSwitch},
    {"at_mm", DeviceType::kLimitSwitch},             {"side", DeviceType::kLimitSwitch},
    {"address", DeviceType::kOled},                  {"snapshots_s", DeviceType::kOled},
    {"address", DeviceType::kTwist},
    {"bounce_ms", DeviceType::kLimitSwitch},
};

std::optional<DeviceType> parse_type(std::string_view name) {
  for (const DeviceKind& kind : device_kinds()) {
    if (kind.name == name) return kind.type;
  }
  return std::nullopt;
}

/// "\"encoder\", \"potentiometer\", … or \"pendulum\"", for the message of an unknown type.
std::string type_names() {
  std::string text;
  const DeviceKindList kinds = device_kinds();
  for (size_t i = 0; i < kinds.size; ++i) {
    if (i > 0) text += i + 1 == kinds.size ? " or " : ", ";
    text += "\"" + std::string(kinds.first[i].name) + "\"";
  }
  return text;
}

bool key_belongs(std::string_view key, DeviceType type) {
  for (const auto& [known, owner] : kTypeKeys) {
    if (known == key && owner == type) return true;
  }
  return false;
}

/// A number in its range into `out`; out of range is reported by the reader.
void read_bounded(TableReader& reader, const char* key, const NumberRange& range, double& out) {
  if (const auto value = reader.number(key, range)) out = *value;
}

/// bounce_ms of a button or limit switch: 0..1000 ms.
void read_bounce_ms(TableReader& reader, DeviceConfig& device) {
  read_bounded(reader, "bounce_ms", NumberRange{0, 1000, false, "ms"}, device.bounce_ms);
}

void read_pulses_per_revolution(TableReader& reader, DeviceConfig& device) {
  if (const auto pulses = reader.integer("pulses_per_revolution", IntegerRange{1, 1000000, "pulses"})) {
    device.pulses_per_revolution = static_cast<int32_t>(*pulses);
  }
}

/// A moment of the run in seconds: [0, duration_s].
NumberRange run_time_range(const ParseContext& context) {
  return NumberRange{0, context.duration_valid ? to_seconds(context.scenario.duration) : ranges::kTimeS.high, false, "s"};
}

void read_pendulum(TableReader& reader, DeviceConfig& device, const ParseContext& context) {
  read_pulses_per_revolution(reader, device);
  read_bounded(reader, "amplitude_deg", NumberRange{0, 170, true, "°"}, device.amplitude_deg);
  read_bounded(reader, "period_s", NumberRange{0.01, 3600, false, "s"}, device.period_s);
  read_bounded(reader, "decay_s", NumberRange{0.01, 1e6, false, "s"}, device.decay_s);
  read_bounded(reader, "release_s", run_time_range(context), device.release_s);
}

/// Whether the scenario's machine has the axis, and its name for messages.
bool machine_has_axis(const MachineConfig& machine, LimitAxis axis) {
  if (std::holds_alternative<CartesianConfig>(machine.kind)) return true;
  if (std::holds_alternative<PolarConfig>(machine.kind)) return axis == LimitAxis::kX;
  return axis != LimitAxis::kZ;
}

std::string_view machine_type_name(const MachineConfig& machine) {
  if (std::holds_alternative<CartesianConfig>(machine.kind)) return "cartesian";
  if (std::holds_alternative<PolarConfig>(machine.kind)) return "polar";
  return "corexy_plotter";
}

/// One path point: [x, y] or [x, y, dwell_s], finite, dwell in [0, 86400].
bool read_path_point(const toml::node& item, DeviceConfig& device) {
  const toml::array* point = item.as_array();
  if (point == nullptr || point->size() < 2 || point->size() > 3) return false;
  double values[3] = {0, 0, 0};
  for (size_t i = 0; i < point->size(); ++i) {
    const auto value = (*point)[i].value<double>();
    if (!value || !std::isfinite(*value)) return false;
    values[i] = *value;
  }
  if (values[2] < 0 || values[2] > 86400) return false;
  device.path_mm.emplace_back(values[0], values[1]);
  device.dwell_s.push_back(values[2]);
  return true;
}

/// path_mm: at least one point.
void read_path(TableReader& reader, DeviceConfig& device) {
  const toml::array* path = reader.array("path_mm", Need::kRequired);
  if (path == nullptr) return;
  for (const toml::node& item : *path) {
    if (!read_path_point(item, device)) {
      reader.error("path_mm", "'path_mm' must be a list of [x, y] or [x, y, dwell_s] points (mm, s; dwell in 0..86400)");
      device.path_mm.clear();
      device.dwell_s.clear();
      return;
    }
  }
  if (device.path_mm.empty()) reader.error("path_mm", "'path_mm' needs at least one point");
}

void read_five_bar_arm(TableReader& reader, DeviceConfig& device, const ParseContext& context) {
  device.pulses_per_revolution = 10000;  // 40,000 counts a turn, as on the original's pantograph
  read_pulses_per_revolution(reader, device);
  read_path(reader, device);
  read_bounded(reader, "speed_mm_per_s", NumberRange{0, 10000, true, "mm/s"}, device.speed_mm_per_s);
  read_bounded(reader, "start_s", run_time_range(context), device.start_s);
  // The joints' home (−60°, 240°) must lie within the turn each stop allows.
  read_bounded(reader, "right_min_deg", NumberRange{-420, -60, false, "°"}, device.right_min_deg);
  read_bounded(reader, "left_max_deg", NumberRange{240, 600, false, "°"}, device.left_max_deg);
}

/// address: a 7-bit I2C address (0x08..0x77, the range not reserved by the I2C standard).
void read_i2c_address(TableReader& reader, DeviceConfig& device) {
  device.i2c_address = device.type == DeviceType::kOled ? 0x3C : 0x3F;
  const auto address = reader.integer("address");
  if (!address) return;
  if (*address >= 0x08 && *address <= 0x77) {
    device.i2c_address = static_cast<int>(*address);
  } else {
    reader.error("address", "'address' must be a 7-bit I2C address in 0x08..0x77, got " + std::to_string(*address));
  }
}

/// snapshots_s: times (s, within the run) at which an OLED's screen is saved as a picture.
void read_snapshots(TableReader& reader, DeviceConfig& device, const ParseContext& context) {
  const toml::array* times = reader.array("snapshots_s");
  if (times == nullptr) return;
  const double last_s = context.duration_valid ? to_seconds(context.scenario.duration) : 86400;
  for (const toml::node& item : *times) {
    const auto time = item.value<double>();
    if (!time || !std::isfinite(*time) || *time < 0 || *time > last_s) {
      reader.error("snapshots_s", "'snapshots_s' must be a list of times in [0, " + format_number(last_s) + "] s");
      device.snapshots_s.clear();
      return;
    }
    device.snapshots_s.push_back(*time);
  }
}

void read_type_keys(TableReader& reader, DeviceConfig& device, const ParseContext& context) {
  std::set<std::string_view> reported;  // a key shared by several kinds is listed once per kind
  for (const auto& [key, owner] : kTypeKeys) {
    if (!key_belongs(key, device.type) && reader.has(key) && reported.insert(key).second) {
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' does not apply to " + std::string(device_with_article(device.type)));
    }
  }
  switch (device.type) {
    case DeviceType::kPendulum:
      read_pendulum(reader, device, context);
      break;
    case DeviceType::kFiveBarArm:
      read_five_bar_arm(reader, device, context);
      break;
    case DeviceType::kOled:
      read_i2c_address(reader, device);
      read_snapshots(reader, device, context);
      break;
    case DeviceType::kTwist:
      read_i2c_address(reader, device);
      break;
    case DeviceType::kEncoder:
      read_pulses_per_revolution(reader, device);
      if (const auto start = reader.integer("start_count", ranges::kEncoderCounts)) device.start_count = *start;
      break;
    case DeviceType::kPotentiometer:
      read_bounded(reader, "position", NumberRange{0, 1, false, ""}, device.position);
      break;
    case DeviceType::kButton:
      read_bounce_ms(reader, device);
      if (const auto level = reader.string("pressed_level")) {
        if (*level == "high" || *level == "low") {
          device.pressed_level_high = *level == "high";
        } else {
          reader.error("pressed_level", "'pressed_level' must be \"high\" or \"low\", got \"" + *level + "\"");
        }
      }
      break;
    case DeviceType::kLimitSwitch: {
      device.bounce_ms = 0;  // a limit switch is clean unless the scenario says otherwise
      read_bounce_ms(reader, device);
      const auto axis = reader.string("axis", Need::kRequired);
      if (axis) {
        if (*axis == "x" || *axis == "y" || *axis == "z") {
          device.axis = *axis == "x" ? LimitAxis::kX : (*axis == "y" ? LimitAxis::kY : LimitAxis::kZ);
        } else {
          reader.error("axis", "'axis' must be \"x\", \"y\" or \"z\", got \"" + *axis + "\"");
        }
      }
      if (const auto at = reader.number("at_mm", ranges::kLengthMm, Need::kRequired)) device.at_mm = *at;
      if (const auto side = reader.string("side")) {
        if (*side == "below" || *side == "above") {
          device.side = *side == "below" ? LimitSide::kBelow : LimitSide::kAbove;
        } else {
          reader.error("side", "'side' must be \"below\" or \"above\", got \"" + *side + "\"");
        }
      }
      const std::optional<MachineConfig>& machine = context.scenario.machine;
      if (!machine) {
        reader.reporter().error(reader.line(), "a limit_switch needs a [machine] to watch");
      } else if (axis && !machine_has_axis(*machine, device.axis)) {
        reader.error("axis", "the " + std::string(machine_type_name(*machine)) + " machine has no '" + *axis + "' axis");
      }
      break;
    }
  }
}


struct DeviceNames {
  std::map<std::string, int> first_lines;
  /// (board, connector) → device using it.
  std::map<std::pair<std::string, Connector>, std::string> connectors;
  /// (board, QWIIC connector, I2C address) → device using it.
  std::map<std::tuple<std::string, Connector, int>, std::string> i2c_addresses;
};

/// A five-bar arm's second encoder: left_connector (required), an encoder connector of its own.
void read_left_connector(TableReader& reader, DeviceConfig& device, const BoardConfig* board, DeviceNames& names) {
  const auto text = reader.string("left_connector", Need::kRequired);
  if (!text) return;
  const std::optional<Connector> connector = parse_connector(*text);
  if (!connector || !device_fits_connector(DeviceType::kFiveBarArm, *connector)) {
    reader.error("left_connector", "'left_connector' must be ENC1 or ENC2, got \"" + *text + "\"");
    return;
  }
  if (board == nullptr) return;
  const auto key = std::make_pair(board->name, *connector);
  if (const auto user = names.connectors.find(key); user != names.connectors.end()) {
    reader.error("left_connector", "connector " + *text + " of board '" + board->name + "' is already used by device '" +
                                       user->second + "'");
    return;
  }
  names.connectors.emplace(key, device.name);
  device.left_connector = *connector;
}

void read_device(const toml::table& table, ParseContext& context, DeviceNames& names) {
  TableReader reader(table, "[[device]]", context.reporter);
  DeviceConfig device;
  device.line = reader.line();
  bool named = false;
  if (const auto name = reader.string("name", Need::kRequired)) {
    if (name->empty()) {
      reader.error("name", "device name must not be empty");
    } else if (const std::string problem = file_name_problem(*name); !problem.empty()) {
      reader.error("name", "device name \"" + *name + "\" names the device's files in the output folder, so it " + problem);
    } else if (const auto first = names.first_lines.find(*name); first != names.first_lines.end()) {
      reader.error("name", "duplicate device name '" + *name + "' (first defined on line " +
                               std::to_string(first->second) + ")");
    } else {
      names.first_lines[*name] = reader.line_of("name");
      context.declared_devices.insert(*name);
      device.name = *name;
      named = true;
    }
  }
  const std::optional<std::string> type_text = reader.string("type", Need::kRequired);
  std::optional<DeviceType> type;
  if (type_text) {
    type = parse_type(*type_text);
    if (!type) {
      reader.error("type", "'type' must be " + type_names() + ", got \"" + *type_text + "\"");
    }
  }
  const BoardConfig* board = nullptr;
  if (const auto board_name = reader.string("board", Need::kRequired)) {
    board = context.scenario.board(*board_name);
    if (board == nullptr) {
      reader.error("board", "unknown board '" + *board_name + "'");
    } else {
      device.board = *board_name;
    }
  }
  if (const auto connector_text = reader.string("connector", Need::kRequired)) {
    const std::optional<Connector> connector = parse_connector(*connector_text);
    if (!connector) {
      reader.error("connector", "unknown connector '" + *connector_text +
                                    "' (connectors are ENC1, ENC2, A1..A4, D1, D2, LIMIT_A..LIMIT_D, QWIIC0 and QWIIC1)");
    } else if (type && !device_fits_connector(*type, *connector)) {
      reader.error("connector", std::string(device_with_article(*type)) + " cannot use connector " + *connector_text +
                                    " (use " + std::string(connectors_for(*type)) + ")");
    } else if (board != nullptr && !module_has_connector(board->module, *connector)) {
      reader.error("connector", "board '" + board->name + "' (" + std::string(module_name(board->module)) +
                                    " module) has no connector " + *connector_text);
    } else if (board != nullptr) {
      const auto key = std::make_pair(board->name, *connector);
      const bool shared_bus = *connector == Connector::kQwiic0 || *connector == Connector::kQwiic1;  // by address
      if (shared_bus) {
      } else if (const auto user = names.connectors.find(key); user != names.connectors.end()) {
        reader.error("connector", "connector " + *connector_text + " of board '" + board->name +
                                      "' is already used by device '" + user->second + "'");
      } else {
        names.connectors.emplace(key, device.name);
      }
      device.connector = *connector;
    }
  }
  if (!type) return;  // the type-specific keys cannot be judged
  device.type = *type;
  if (device.type == DeviceType::kFiveBarArm) read_left_connector(reader, device, board, names);
  read_type_keys(reader, device, context);
  if (device.i2c_address >= 0 && board != nullptr) {
    const auto key = std::make_tuple(board->name, device.connector, device.i2c_address);
    if (const auto user = names.i2c_addresses.find(key); user != names.i2c_addresses.end()) {
      reader.error(reader.has("address") ? "address" : "connector",
                   "address " + std::to_string(device.i2c_address) + " on " + std::string(connector_name(device.connector)) +
                       " of board '" + board->name + "' is already used by device '" + user->second + "'");
    } else {
      names.i2c_addresses.emplace(key, device.name);
    }
  }
  reader.finish();
  if (named) context.scenario.devices.push_back(std::move(device));
}

}  // namespace

void read_devices(TableReader& top, ParseContext& context) {
  DeviceNames names;
  for_each_table(top, "device", [&](const toml::table& table) { read_device(table, context, names); });
}

}  // namespace stepdance::sim::scenario
