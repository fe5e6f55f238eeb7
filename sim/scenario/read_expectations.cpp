// [[expect]]: end-of-run checks (motor steps, pen position, strokes, port pulses, cables, rejections).
#include <algorithm>
#include <cmath>
#include <utility>

#include "kinds/devices/five_bar_arm.hpp"
#include "kinds/devices/oled.hpp"
#include "kinds/machines/cartesian.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"
#include "scenario/line_pattern.hpp"

namespace stepdance::sim::scenario {

namespace {

/// The key that decides each kind of check, in the order they are looked for.
constexpr std::pair<const char*, ExpectationType> kChecks[] = {
    {"motor", ExpectationType::kMotorSteps},
    {"pen_mm", ExpectationType::kPenPosition},
    {"strokes", ExpectationType::kStrokes},
    {"bounds_mm", ExpectationType::kBounds},
    {"drawn_mm", ExpectationType::kDrawnLength},
    {"z_mm", ExpectationType::kZPosition},
    {"extruded_per_mm", ExpectationType::kExtrusionRatio},
    {"traces", ExpectationType::kTraces},
    {"cable_counts_match", ExpectationType::kCableCountsMatch},
    {"rejected", ExpectationType::kRejected},
    {"port", ExpectationType::kPortPulses},
    {"host", ExpectationType::kHostReplies},
    {"screen", ExpectationType::kScreenText},
    {"i2c_loop_pass_max_us", ExpectationType::kI2cLoopTime},
};

/// Keys that only go with one check (port also goes with rejected, handled apart).
constexpr std::pair<const char*, const char*> kDetails[] = {
    {"steps", "motor"},  {"relative_tolerance", "extruded_per_mm"}, {"offset_mm", "traces"}, {"from_point", "traces"}, {"axis", "port"},      {"forward", "port"}, {"reverse", "port"},
    {"reply", "host"},   {"replies", "host"},        {"count", "host"},     {"within_ms", "host"}, {"after", "host"},
    {"completed", "host"},
    {"shows", "screen"}, {"row", "screen"}, {"board", "i2c_loop_pass_max_us"},
};

constexpr const char* kSignalLetters = "XYRTZE";

std::optional<std::pair<const char*, ExpectationType>> choose_check(TableReader& reader) {
  std::optional<std::pair<const char*, ExpectationType>> chosen;
  for (const auto& [key, type] : kChecks) {
    if (!reader.has(key)) continue;
    // 'port' is the subject of a 'rejected' check, not a check of its own there.
    if (type == ExpectationType::kPortPulses && chosen && chosen->second == ExpectationType::kRejected) continue;
    if (chosen) {
      reader.accept(key);
      reader.error(key, std::string("an [[expect]] checks one thing, but has both '") + chosen->first + "' and '" +
                            key + "'");
      return std::nullopt;
    }
    chosen = std::make_pair(key, type);
  }
  if (!chosen) {
    reader.reporter().error(reader.line(),
                            "an [[expect]] needs one check: motor, pen_mm, strokes, bounds_mm, drawn_mm, z_mm, extruded_per_mm, traces, port, "
                            "cable_counts_match, rejected, host, screen or i2c_loop_pass_max_us");
  }
  return chosen;
}

bool read_motor(TableReader& reader, Expectation& check, const ParseContext& context) {
  bool ok = true;
  const auto text = reader.string("motor");
  if (const auto steps = reader.integer("steps", Need::kRequired)) {
    check.steps = *steps;
  } else {
    ok = false;
  }
  if (!text) return false;
  const std::optional<SplitRef> split = split_ref(*text);
  if (!split || split->rest.size() != 1 || split->rest[0] < 'A' || split->rest[0] > 'D') {
    reader.error("motor", "'motor' must look like \"board:A\" (a socket), got \"" + *text + "\"");
    return false;
  }
  const BoardConfig* board = context.scenario.board(split->board);
  if (board == nullptr) {
    reader.error("motor", "unknown board '" + split->board + "'");
    return false;
  }
  const SocketConfig* socket = board->socket(split->rest[0]);
  if (socket == nullptr || socket->device != SocketDevice::kStepper) {
    reader.error("motor", "socket " + split->rest + " of board '" + board->name + "' holds no stepper");
    return false;
  }
  check.motor = PortRef{board->name, split->rest[0]};
  return ok;
}

/// The checks that take a tolerance_mm.
bool takes_tolerance(ExpectationType type) {
  return type == ExpectationType::kPenPosition || type == ExpectationType::kBounds ||
         type == ExpectationType::kDrawnLength || type == ExpectationType::kZPosition ||
         type == ExpectationType::kTraces;
}

/// tolerance_mm (>= 0, finite) and the [machine] every pen check needs.
bool read_tolerance(TableReader& reader, Expectation& check, const ParseContext& context, const char* key) {
  bool ok = true;
  if (const auto tolerance = reader.number("tolerance_mm")) {
    if (*tolerance >= 0 && std::isfinite(*tolerance)) {
      check.tolerance_mm = *tolerance;
    } else {
      reader.error("tolerance_mm", "'tolerance_mm' must be a finite number >= 0, got " + format_number(*tolerance));
      ok = false;
    }
  }
  if (!context.scenario.machine) {
    reader.error(key, std::string("'") + key + "' needs a [machine]");
    ok = false;
  }
  return ok;
}

bool read_pen(TableReader& reader, Expectation& check, const ParseContext& context) {
  const toml::array* pair = reader.array("pen_mm");
  double values[2] = {0, 0};
  bool ok = pair != nullptr && read_number_pair(*pair, values);
  if (pair != nullptr && !ok) reader.error("pen_mm", "'pen_mm' must be two numbers [x, y]");
  check.pen_x_mm = values[0];
  check.pen_y_mm = values[1];
  return read_tolerance(reader, check, context, "pen_mm") && ok;
}

/// bounds_mm = [x_min, y_min, x_max, y_max], finite, min <= max.
bool read_bounds(TableReader& reader, Expectation& check, const ParseContext& context) {
  const toml::array* box = reader.array("bounds_mm");
  bool ok = box != nullptr && box->size() == 4;
  for (size_t i = 0; ok && i < 4; ++i) {
    const auto value = (*box)[i].value<double>();
    ok = value.has_value() && std::isfinite(*value);
    if (ok) check.bounds_mm[i] = *value;
  }
  ok = ok && check.bounds_mm[0] <= check.bounds_mm[2] && check.bounds_mm[1] <= check.bounds_mm[3];
  if (box != nullptr && !ok) {
    reader.error("bounds_mm", "'bounds_mm' must be four numbers [x_min, y_min, x_max, y_max] with min <= max");
  }
  return read_tolerance(reader, check, context, "bounds_mm") && ok;
}

/// z_mm = final z (the machine needs a z axis: cartesian with a 'z' socket).
bool read_z(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto z = reader.number("z_mm");
  bool ok = z.has_value() && std::isfinite(*z);
  if (z && !ok) reader.error("z_mm", "'z_mm' must be a finite number");
  if (ok) check.z_mm = *z;
  const auto* cartesian = context.scenario.machine ? context.scenario.machine->settings_as<CartesianConfig>() : nullptr;
  if (context.scenario.machine && (cartesian == nullptr || !cartesian->z)) {
    reader.error("z_mm", "'z_mm' needs a cartesian [machine] with a 'z' socket");
    ok = false;
  }
  return read_tolerance(reader, check, context, "z_mm") && ok;
}

/// extruded_per_mm = ratio, relative_tolerance (default 0.01): the machine needs an extruder.
bool read_extrusion(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto ratio = reader.number("extruded_per_mm");
  bool ok = ratio.has_value() && std::isfinite(*ratio) && *ratio > 0;
  if (ratio && !ok) reader.error("extruded_per_mm", "'extruded_per_mm' must be a finite number > 0, got " + format_number(*ratio));
  if (ok) check.extruded_per_mm = *ratio;
  if (const auto tolerance = reader.number("relative_tolerance")) {
    if (*tolerance > 0 && *tolerance < 1) {
      check.relative_tolerance = *tolerance;
    } else {
      reader.error("relative_tolerance", "'relative_tolerance' must be in (0, 1), got " + format_number(*tolerance));
      ok = false;
    }
  }
  const auto* cartesian = context.scenario.machine ? context.scenario.machine->settings_as<CartesianConfig>() : nullptr;
  if (cartesian == nullptr || !cartesian->e) {
    reader.error("extruded_per_mm", "'extruded_per_mm' needs a cartesian [machine] with an 'e' socket");
    ok = false;
  }
  return ok;
}

/// traces = "<five_bar_arm device>", offset_mm = [dx, dy], from_point = N, tolerance_mm.
bool read_traces(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto name = reader.string("traces");
  bool ok = name.has_value();
  const DeviceConfig* device = name ? context.scenario.device(*name) : nullptr;
  const FiveBarArmConfig* arm = device != nullptr ? device->settings_as<FiveBarArmConfig>() : nullptr;
  if (name && arm == nullptr) {
    reader.error("traces", "'traces' must name a five_bar_arm device, got '" + *name + "'");
    ok = false;
  }
  if (ok) check.traces = *name;
  if (const toml::array* offset = reader.array("offset_mm")) {
    if (!read_number_pair(*offset, check.offset_mm)) {
      reader.error("offset_mm", "'offset_mm' must be two numbers [dx, dy]");
      ok = false;
    }
  }
  if (const auto from = reader.integer("from_point")) {
    const int64_t points = arm != nullptr ? static_cast<int64_t>(arm->path_mm.size()) : 0;
    if (*from >= 0 && (device == nullptr || *from < points)) {
      check.from_point = *from;
    } else {
      reader.error("from_point", "'from_point' must index the arm's path_mm (0.." + std::to_string(points - 1) +
                                     "), got " + std::to_string(*from));
      ok = false;
    }
  }
  return read_tolerance(reader, check, context, "traces") && ok;
}

/// screen = "<oled device>", shows = "text", row = 0..3 (optional).
bool read_screen(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto name = reader.string("screen");
  bool ok = name.has_value();
  const DeviceConfig* device = name ? context.scenario.device(*name) : nullptr;
  if (name && (device == nullptr || device->settings_as<OledConfig>() == nullptr)) {
    reader.error("screen", "'screen' must name an oled device, got '" + *name + "'");
    ok = false;
  }
  if (ok) check.screen = *name;
  if (const auto text = reader.string("shows", Need::kRequired)) {
    if (text->size() > 21) {
      reader.error("shows", "'shows' can be at most 21 characters (a row of the 128x32 screen)");
      ok = false;
    }
    check.shows = *text;
  } else {
    ok = false;
  }
  if (const auto row = reader.integer("row")) {
    if (*row < 0 || *row > 3) {
      reader.error("row", "'row' must be 0..3, got " + std::to_string(*row));
      ok = false;
    }
    check.screen_row = *row;
  }
  return ok;
}

/// i2c_loop_pass_max_us = bound (µs, > 0), board = "<board>".
bool read_i2c_loop_time(TableReader& reader, Expectation& check, const ParseContext& context) {
  bool ok = true;
  if (const auto bound = reader.number("i2c_loop_pass_max_us")) {
    if (!std::isfinite(*bound) || *bound <= 0) {
      reader.error("i2c_loop_pass_max_us", "'i2c_loop_pass_max_us' must be a time > 0 (µs)");
      ok = false;
    }
    check.i2c_loop_pass_max_us = *bound;
  } else {
    ok = false;
  }
  if (const auto board = reader.string("board", Need::kRequired)) {
    if (context.scenario.board(*board) == nullptr) {
      reader.error("board", "unknown board '" + *board + "'");
      ok = false;
    }
    check.i2c_board = *board;
  } else {
    ok = false;
  }
  return ok;
}

bool read_drawn(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto length = reader.number("drawn_mm");
  bool ok = length.has_value();
  if (length && (!std::isfinite(*length) || *length < 0)) {
    reader.error("drawn_mm", "'drawn_mm' must be a finite length >= 0, got " + format_number(*length));
    ok = false;
  }
  if (ok) check.drawn_mm = *length;
  return read_tolerance(reader, check, context, "drawn_mm") && ok;
}

bool read_port_check(TableReader& reader, Expectation& check, ParseContext& context, bool rejected) {
  bool ok = true;
  if (const auto text = reader.string("port", Need::kRequired)) {
    if (const auto port = parse_port_line(*text, "port", reader.line_of("port"), context)) {
      check.port = *port;
      if (rejected && port->output) {
        reader.error("port", "'rejected' counts pulses an input port refused: 'port' must be \"board:IN_" +
                                 std::string(1, port->port) + "\"");
        ok = false;
      }
    } else {
      ok = false;
    }
  } else {
    ok = false;
  }
  if (rejected) {
    if (const auto count = reader.integer("rejected")) {
      check.rejected = *count;
    } else {
      ok = false;
    }
    return ok;
  }
  if (const auto axis = reader.string("axis", Need::kRequired)) {
    const std::string_view letters(kSignalLetters);
    const size_t index = axis->size() == 1 ? letters.find((*axis)[0]) : std::string_view::npos;
    if (index == std::string_view::npos) {
      reader.error("axis", "'axis' must be one of \"X\", \"Y\", \"R\", \"T\", \"Z\", \"E\", got \"" + *axis + "\"");
      ok = false;
    } else {
      check.signal = static_cast<int>(index);
    }
  } else {
    ok = false;
  }
  check.forward = reader.integer("forward");
  check.reverse = reader.integer("reverse");
  if (!reader.has("forward") && !reader.has("reverse")) {
    reader.reporter().error(reader.line(), "a 'port' check needs 'forward', 'reverse' or both");
    ok = false;
  }
  return ok;
}

bool valid_pattern(TableReader& reader, const char* key, const std::string& pattern) {
  const std::string problem = pattern_problem(pattern);
  if (!problem.empty()) reader.error(key, "'" + std::string(key) + "' " + problem);
  return problem.empty();
}

/// host = "board" with reply/replies (+ count, within_ms, after), or completed = true.
bool read_host_check(TableReader& reader, Expectation& check, const ParseContext& context) {
  const auto board = reader.string("host");
  if (!board) return false;
  check.host = *board;
  bool ok = true;
  const bool has_client = std::any_of(context.scenario.hosts.begin(), context.scenario.hosts.end(),
                                      [&](const HostClientConfig& host) { return host.board == *board; });
  if (!has_client) {
    reader.error("host", "no [[host]] client on board '" + *board + "'");
    ok = false;
  }
  if (reader.has("completed")) {
    check.type = ExpectationType::kHostCompleted;
    const auto completed = reader.boolean("completed");
    if (completed && !*completed) {
      reader.error("completed", "'completed' can only be true");
      ok = false;
    }
    for (const char* other : {"reply", "replies", "count", "within_ms", "after"}) {
      if (!reader.has(other)) continue;
      reader.accept(other);
      reader.error(other, std::string("'") + other + "' does not go with 'completed'");
      ok = false;
    }
    return ok && completed.has_value();
  }
  if (reader.has("reply") == reader.has("replies")) {
    reader.reporter().error(reader.line(), "a 'host' check needs 'reply' (one regex) or 'replies' (regexes in order)");
    reader.accept("reply");
    reader.accept("replies");
    return false;
  }
  if (const auto reply = reader.string("reply")) {
    ok = valid_pattern(reader, "reply", *reply) && ok;
    check.replies.push_back(*reply);
  } else if (const toml::array* replies = reader.array("replies")) {
    for (const toml::node& item : *replies) {
      const auto* text = item.as_string();
      if (text == nullptr) {
        reader.error("replies", "'replies' must be a list of strings");
        return false;
      }
      ok = valid_pattern(reader, "replies", text->get()) && ok;
      check.replies.push_back(text->get());
    }
    if (check.replies.empty()) {
      reader.error("replies", "'replies' must not be empty");
      ok = false;
    }
  } else {
    ok = false;
  }
  if (const auto count = reader.integer("count")) {
    if (*count < 0 || check.replies.size() != 1) {
      reader.error("count", "'count' must be >= 0 and goes with a single 'reply'");
      ok = false;
    }
    check.count = *count;
  }
  if (reader.has("within_ms")) {
    const auto within = reader.number("within_ms", NumberRange{0, ranges::kTimeMs.high, true, "ms"});
    if (within) check.within = from_seconds(*within / 1e3);
    ok = ok && within.has_value();
  }
  if (const auto after = reader.string("after")) {
    ok = valid_pattern(reader, "after", *after) && ok;
    check.after = *after;
    if (!check.within) {
      reader.error("after", "'after' goes with 'within_ms'");
      ok = false;
    }
  }
  return ok;
}

void read_expectation(const toml::table& table, ParseContext& context) {
  TableReader reader(table, "[[expect]]", context.reporter);
  Expectation check;
  check.line = reader.line();
  const auto chosen = choose_check(reader);
  if (!chosen) return;
  check.type = chosen->second;
  bool ok = true;
  if (!takes_tolerance(check.type) && reader.has("tolerance_mm")) {
    reader.accept("tolerance_mm");
    reader.error("tolerance_mm", "'tolerance_mm' only goes with 'pen_mm', 'bounds_mm', 'drawn_mm', 'z_mm' or 'traces'");
    ok = false;
  }
  for (const auto& [key, owner] : kDetails) {
    const bool belongs = std::string_view(owner) == chosen->first;
    if (!belongs && reader.has(key)) {
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' only goes with '" + owner + "'");
      ok = false;
    }
  }
  switch (check.type) {
    case ExpectationType::kMotorSteps:
      ok = read_motor(reader, check, context) && ok;
      break;
    case ExpectationType::kPenPosition:
      ok = read_pen(reader, check, context) && ok;
      break;
    case ExpectationType::kBounds:
      ok = read_bounds(reader, check, context) && ok;
      break;
    case ExpectationType::kDrawnLength:
      ok = read_drawn(reader, check, context) && ok;
      break;
    case ExpectationType::kZPosition:
      ok = read_z(reader, check, context) && ok;
      break;
    case ExpectationType::kExtrusionRatio:
      ok = read_extrusion(reader, check, context) && ok;
      break;
    case ExpectationType::kTraces:
      ok = read_traces(reader, check, context) && ok;
      break;
    case ExpectationType::kStrokes:
      if (const auto strokes = reader.integer("strokes")) {
        check.strokes = *strokes;
        if (!context.scenario.machine) {
          reader.error("strokes", "'strokes' needs a [machine]");
          ok = false;
        }
      } else {
        ok = false;
      }
      break;
    case ExpectationType::kCableCountsMatch:
      if (const auto match = reader.boolean("cable_counts_match")) {
        if (!*match) {
          reader.error("cable_counts_match", "'cable_counts_match' can only be true");
          ok = false;
        } else if (context.scenario.cables.empty()) {
          reader.error("cable_counts_match", "'cable_counts_match' needs at least one [[cable]]");
          ok = false;
        }
      } else {
        ok = false;
      }
      break;
    case ExpectationType::kPortPulses:
    case ExpectationType::kRejected:
      ok = read_port_check(reader, check, context, check.type == ExpectationType::kRejected) && ok;
      break;
    case ExpectationType::kHostReplies:
    case ExpectationType::kHostCompleted:
      ok = read_host_check(reader, check, context) && ok;
      break;
    case ExpectationType::kScreenText:
      ok = read_screen(reader, check, context) && ok;
      break;
    case ExpectationType::kI2cLoopTime:
      ok = read_i2c_loop_time(reader, check, context) && ok;
      break;
  }
  reader.finish();
  if (ok) context.scenario.expectations.push_back(std::move(check));
}

}  // namespace

void read_expectations(TableReader& top, ParseContext& context) {
  for_each_table(top, "expect", [&](const toml::table& table) { read_expectation(table, context); });
}

}  // namespace stepdance::sim::scenario
