// [[board]] and [board.sockets]: modules, sketches, loop timing and driver sockets.
#include <filesystem>
#include <map>

#include "kinds/board_registry.hpp"
#include "scenario/file_names.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

constexpr int kFramePeriodUs = 40;

bool valid_microsteps(int64_t value) { return value >= 1 && value <= 64 && (value & (value - 1)) == 0; }

/// A stepper socket's keys: microsteps, full_steps_per_rev, reversed (and no servo 'build').
bool read_stepper_socket(TableReader& reader, SocketConfig& socket) {
  socket.device = SocketDevice::kStepper;
  bool ok = true;
  if (const auto microsteps = reader.integer("microsteps")) {
    if (valid_microsteps(*microsteps)) {
      socket.microsteps = static_cast<int>(*microsteps);
    } else {
      reader.error("microsteps", "'microsteps' must be 1, 2, 4, 8, 16, 32 or 64, got " + std::to_string(*microsteps));
      ok = false;
    }
  }
  if (reader.has("full_steps_per_rev")) {
    const auto full_steps = reader.integer("full_steps_per_rev", IntegerRange{1, 100000, "full steps"});
    if (full_steps) socket.full_steps_per_rev = static_cast<int>(*full_steps);
    ok = ok && full_steps.has_value();
  }
  if (const auto reversed = reader.boolean("reversed")) socket.reversed = *reversed;
  if (reader.has("build")) {
    reader.accept("build");
    reader.error("build", "'build' does not apply to a stepper");
    ok = false;
  }
  return ok;
}

/// A servo socket's keys: build (and none of a stepper's).
bool read_servo_socket(TableReader& reader, SocketConfig& socket) {
  socket.device = SocketDevice::kServo;
  bool ok = true;
  if (const auto build = reader.string("build")) {
    if (*build == "90deg") {
      socket.build = ServoBuild::k90deg;
    } else if (*build == "180deg") {
      socket.build = ServoBuild::k180deg;
    } else {
      reader.error("build", "'build' must be \"90deg\" or \"180deg\", got \"" + *build + "\"");
      ok = false;
    }
  }
  for (const char* key : {"microsteps", "full_steps_per_rev", "reversed"}) {
    if (reader.has(key)) {
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' does not apply to a servo");
      ok = false;
    }
  }
  return ok;
}

std::optional<SocketConfig> read_socket(char port, const toml::node& value, Reporter& reporter) {
  const toml::table* table = value.as_table();
  if (table == nullptr) {
    reporter.error(line_of(value), std::string("socket ") + port +
                                       " must be a table, e.g. { device = \"stepper\" }, not " +
                                       std::string(type_phrase(value)));
    return std::nullopt;
  }
  TableReader reader(*table, std::string("socket ") + port, reporter);
  SocketConfig socket;
  socket.port = port;
  socket.line = reader.line();
  bool ok = true;
  const std::optional<std::string> device = reader.string("device", Need::kRequired);
  if (!device) {
    ok = false;
  } else if (*device == "stepper") {
    ok = read_stepper_socket(reader, socket);
  } else if (*device == "servo") {
    ok = read_servo_socket(reader, socket);
  } else {
    reader.error("device", "'device' must be \"stepper\" or \"servo\", got \"" + *device + "\"");
    ok = false;
  }
  reader.finish();
  if (!ok) return std::nullopt;
  return socket;
}

void read_sockets(TableReader& board_reader, BoardConfig& board, ParseContext& context) {
  const toml::table* sockets = board_reader.table("sockets");
  if (sockets == nullptr) return;
  if (!board.module->has_drivers) {
    context.reporter.error(line_of(*sockets),
                           "a " + std::string(module_name(*board.module)) + " module has no driver sockets");
    return;
  }
  for (const auto& [key, value] : *sockets) {
    const std::string_view name = key.str();
    if (name.size() != 1 || !module_has_output_port(*board.module, name[0])) {
      context.reporter.error(
          static_cast<int>(key.source().begin.line),
          "unknown socket '" + std::string(name) + "' (sockets are " + socket_letters(*board.module) + ")");
      continue;
    }
    if (const auto socket = read_socket(name[0], value, context.reporter)) board.sockets.push_back(*socket);
  }
}

// `sketch` (required) and `image` (a firmware ELF, optional): each resolved against the scenario's
// folder and checked to exist. A board with an image may leave out its sketch.
void read_program(TableReader& reader, BoardConfig& board, ParseContext& context) {
  if (const auto image = reader.string("image")) {
    board.image = context.resolve(*image);
    std::error_code error;
    if (!std::filesystem::is_regular_file(board.image, error))
      reader.error("image", "firmware image not found: " + board.image);
  }
  const Need need = board.image.empty() ? Need::kRequired : Need::kOptional;
  if (const auto sketch = reader.string("sketch", need)) {
    board.sketch = context.resolve(*sketch);
    std::error_code error;
    if (!std::filesystem::is_regular_file(board.sketch, error)) {
      reader.error("sketch", "sketch not found: " + board.sketch);
    }
  }
}

void read_board(const toml::table& table, ParseContext& context, std::map<std::string, int>& first_lines) {
  TableReader reader(table, "[[board]]", context.reporter);
  BoardConfig board;
  board.line = reader.line();
  const std::optional<std::string> name = reader.string("name", Need::kRequired);
  bool named = false;
  if (name) {
    if (name->empty() || name->find(':') != std::string::npos) {
      reader.error("name", "board name \"" + *name + "\" must be non-empty and contain no ':'");
    } else if (const std::string problem = file_name_problem(*name); !problem.empty()) {
      reader.error("name", "board name \"" + *name +
                               "\" names its SD card folder (<name>.sd in the output folder), so it " + problem);
    } else if (const auto first = first_lines.find(*name); first != first_lines.end()) {
      reader.error(
          "name", "duplicate board name '" + *name + "' (first defined on line " + std::to_string(first->second) + ")");
    } else {
      first_lines[*name] = reader.line_of("name");
      board.name = *name;
      named = true;
    }
  }
  read_program(reader, board, context);
  if (const auto module = reader.string("module")) {
    if (const BoardDefinition* found = find_board(*module)) {
      board.module = found;
    } else {
      reader.error("module", "'module' must be " + board_names() + ", got \"" + *module + "\"");
    }
  }
  if (const auto period = reader.integer("loop_period_us", ranges::kLoopPeriodUs)) board.loop_period_us = *period;
  if (const auto phase = reader.integer("frame_phase_us", IntegerRange{0, kFramePeriodUs - 1, "µs"})) {
    board.frame_phase_us = static_cast<int>(*phase);
  }
  read_sockets(reader, board, context);
  read_sd_card(reader, board, context);
  reader.finish();
  if (named) context.scenario.boards.push_back(std::move(board));
}

}  // namespace

void read_boards(TableReader& top, ParseContext& context) {
  std::map<std::string, int> first_lines;
  for_each_table(top, "board", [&](const toml::table& table) { read_board(table, context, first_lines); });
}

}  // namespace stepdance::sim::scenario
