// [machine]: CoreXY plotter, cartesian XYZE or polar turntable, bound to a board's sockets.
#include <map>

#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Checks the sockets a machine uses: each holds the right device and none is used twice.
class SocketChecker {
 public:
  SocketChecker(TableReader& reader, const BoardConfig* board) : reader_(reader), board_(board) {}

  /// Reads `key` as a socket letter (default `fallback`, if any) that must hold `device`.
  std::optional<char> take(std::string_view key, SocketDevice device, std::optional<char> fallback) {
    const bool given = reader_.has(key);
    std::optional<char> port = read_socket_letter(reader_, key);
    if (given && !port) return std::nullopt;
    if (!given) port = fallback;
    if (!port || board_ == nullptr) return port;
    const std::string what = device == SocketDevice::kStepper ? "a stepper" : "a servo";
    const std::string where = std::string("socket ") + *port + " of board '" + board_->name + "'";
    const SocketConfig* socket = board_->socket(*port);
    if (socket == nullptr) {
      reader_.error(key, "'" + std::string(key) + "' needs " + what + " in " + where + ", but it is empty");
    } else if (socket->device != device) {
      const std::string holds = socket->device == SocketDevice::kStepper ? "a stepper" : "a servo";
      reader_.error(key, "'" + std::string(key) + "' needs " + what + " in " + where + ", but it holds " + holds);
    } else if (const auto user = users_.find(*port); user != users_.end()) {
      reader_.error(key, "'" + std::string(key) + "' uses socket " + std::string(1, *port) + ", already used by '" +
                             user->second + "'");
    }
    users_.emplace(*port, std::string(key));
    return port;
  }

 private:
  TableReader& reader_;
  const BoardConfig* board_;
  std::map<char, std::string> users_;
};

/// Reads a number in (0, 10^6] `unit` into `target`.
void positive(TableReader& reader, std::string_view key, const char* unit, double& target) {
  if (const auto value = reader.number(key, NumberRange{0, 1000000, true, unit})) target = *value;
}

CorexyConfig read_corexy(TableReader& reader, SocketChecker& sockets) {
  CorexyConfig config;
  config.motor_a = sockets.take("motor_a", SocketDevice::kStepper, 'A').value_or('A');
  config.motor_b = sockets.take("motor_b", SocketDevice::kStepper, 'B').value_or('B');
  config.pen_servo = sockets.take("pen_servo", SocketDevice::kServo, 'C').value_or('C');
  positive(reader, "steps_per_mm", "steps/mm", config.steps_per_mm);
  positive(reader, "pen_down_below_us", "µs", config.pen_down_below_us);
  if (const toml::array* travel = reader.array("travel_mm")) {
    double values[2] = {0, 0};
    const bool ok = read_number_pair(*travel, values) && in_range(values[0], ranges::kPositiveLengthMm) &&
                    in_range(values[1], ranges::kPositiveLengthMm);
    if (ok) {
      config.travel_x_mm = values[0];
      config.travel_y_mm = values[1];
    } else {
      reader.error("travel_mm", "'travel_mm' must be two numbers in " + describe(ranges::kPositiveLengthMm) +
                                    ", e.g. [300, 218]");
    }
  }
  if (const toml::array* start = reader.array("start_mm")) {
    double values[2] = {0, 0};
    if (read_number_pair(*start, values) && in_range(values[0], ranges::kLengthMm) &&
        in_range(values[1], ranges::kLengthMm)) {
      config.start_x_mm = values[0];
      config.start_y_mm = values[1];
    } else {
      reader.error("start_mm", "'start_mm' must be two numbers in " + describe(ranges::kLengthMm) + ", e.g. [120.5, 80]");
    }
  }
  return config;
}

CartesianConfig read_cartesian(TableReader& reader, SocketChecker& sockets) {
  CartesianConfig config;
  config.x = sockets.take("x", SocketDevice::kStepper, std::nullopt);
  config.y = sockets.take("y", SocketDevice::kStepper, std::nullopt);
  config.z = sockets.take("z", SocketDevice::kStepper, std::nullopt);
  config.e = sockets.take("e", SocketDevice::kStepper, std::nullopt);
  if (const toml::table* per_axis = reader.table("steps_per_mm")) {
    TableReader axes(*per_axis, "steps_per_mm", reader.reporter());
    positive(axes, "x", "steps/mm", config.x_steps_per_mm);
    positive(axes, "y", "steps/mm", config.y_steps_per_mm);
    positive(axes, "z", "steps/mm", config.z_steps_per_mm);
    positive(axes, "e", "steps/mm", config.e_steps_per_mm);
    axes.finish();
  }
  if (const auto threshold = reader.number("pen_down_at_or_below_mm", ranges::kLengthMm)) config.pen_down_at_or_below_mm = *threshold;
  if (const auto draw = reader.string("draw")) {
    if (*draw == "z" || *draw == "extruding") {
      config.draws_while_extruding = *draw == "extruding";
    } else {
      reader.error("draw", "'draw' must be \"z\" (the pen is down while z is low) or \"extruding\", got \"" + *draw + "\"");
    }
    if (config.draws_while_extruding && !config.e) reader.error("draw", "'draw = \"extruding\"' needs an 'e' socket");
  }
  return config;
}

PolarConfig read_polar(TableReader& reader, SocketChecker& sockets) {
  PolarConfig config;
  config.angle = sockets.take("angle", SocketDevice::kStepper, 'A').value_or('A');
  config.radius = sockets.take("radius", SocketDevice::kStepper, 'B').value_or('B');
  config.pen_servo = sockets.take("pen_servo", SocketDevice::kServo, std::nullopt);
  positive(reader, "steps_per_rev", "steps", config.steps_per_rev);
  positive(reader, "steps_per_mm", "steps/mm", config.steps_per_mm);
  positive(reader, "pen_down_below_us", "µs", config.pen_down_below_us);
  return config;
}

}  // namespace

void read_machine(TableReader& top, ParseContext& context) {
  const toml::table* table = top.table("machine");
  if (table == nullptr) return;
  TableReader reader(*table, "[machine]", context.reporter);
  MachineConfig machine;
  machine.line = reader.line();
  const BoardConfig* board = nullptr;
  if (const auto name = reader.string("board", Need::kRequired)) {
    board = context.scenario.board(*name);
    if (board == nullptr) {
      reader.error("board", "unknown board '" + *name + "'");
    } else if (board->module == Module::kBasic) {
      reader.error("board", "board '" + *name + "' is a basic module, which has no driver sockets");
      board = nullptr;
    } else {
      machine.board = *name;
    }
  }
  SocketChecker sockets(reader, board);
  const std::optional<std::string> type = reader.string("type", Need::kRequired);
  if (!type) return;
  if (*type == "corexy_plotter") {
    machine.kind = read_corexy(reader, sockets);
  } else if (*type == "cartesian") {
    machine.kind = read_cartesian(reader, sockets);
  } else if (*type == "polar") {
    machine.kind = read_polar(reader, sockets);
  } else {
    // Without a known type, the other keys cannot be judged: report only the type.
    reader.error("type", "'type' must be \"corexy_plotter\", \"cartesian\" or \"polar\", got \"" + *type + "\"");
    return;
  }
  reader.finish();
  context.scenario.machine = std::move(machine);
}

}  // namespace stepdance::sim::scenario
