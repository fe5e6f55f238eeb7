// [[at]]: the timeline of user actions (turn, press, release, click, set, serial).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "kinds/device_registry.hpp"
#include "kinds/devices/encoder.hpp"
#include "scenario/names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

constexpr std::pair<const char*, ActionType> kActions[] = {
    {"turn", ActionType::kTurn},   {"press", ActionType::kPress}, {"release", ActionType::kRelease},
    {"click", ActionType::kClick}, {"set", ActionType::kSet},     {"serial", ActionType::kSerial},
};

/// Keys that go with one action each.
constexpr std::pair<const char*, ActionType> kActionKeys[] = {
    {"counts", ActionType::kTurn},  {"over_s", ActionType::kTurn}, {"hold_ms", ActionType::kClick},
    {"position", ActionType::kSet}, {"text", ActionType::kSerial}, {"file", ActionType::kSerial},
};

/// Seconds to simulated time, saturating far beyond any valid duration so huge values cannot overflow.
SimTime to_time(double seconds) {
  constexpr double kLimitS = 1e6;
  return from_seconds(std::clamp(seconds, -kLimitS, kLimitS));
}

const char* action_name(ActionType type) {
  for (const auto& [name, value] : kActions) {
    if (value == type) return name;
  }
  return "?";
}

/// Whether `end` lies within the run; reports at `key` otherwise.
void check_end(TableReader& reader, const ParseContext& context, std::string_view key, SimTime end,
               const std::string& what) {
  if (!context.duration_valid || end <= context.scenario.duration) return;
  reader.error(key, what + " at " + format_number(to_seconds(end)) + " s, after the end of the run (duration_s = " +
                        format_number(to_seconds(context.scenario.duration)) + ")");
}

bool read_target(TableReader& reader, Action& action, const ParseContext& context) {
  const char* key = action_name(action.type);
  const std::optional<std::string> target = reader.string(key);
  if (!target) return false;
  action.target = *target;
  if (action.type == ActionType::kSerial) {
    if (context.scenario.board(*target) != nullptr) return true;
    reader.error(key, "unknown board '" + *target + "'");
    return false;
  }
  const DeviceConfig* device = context.scenario.device(*target);
  if (device == nullptr) {
    if (context.declared_devices.count(*target) == 0) reader.error(key, "unknown device '" + *target + "'");
    return false;
  }
  if (!device->kind->takes(action.type)) {
    // Named after the first kind that takes it: `turn` needs "an encoder".
    const DeviceKind* wanted = first_kind_taking(action.type);
    const std::string needs = wanted != nullptr ? std::string(wanted->with_article) : "another device";
    reader.error(key, "'" + std::string(key) + "' needs " + needs + ", but '" + *target + "' is " +
                          std::string(device->kind->with_article));
    return false;
  }
  return true;
}

/// Reports the keys of kActionKeys that go with another action; false if there was one.
bool refuse_other_action_keys(TableReader& reader, ActionType type) {
  bool ok = true;
  for (const auto& [key, owner] : kActionKeys) {
    if (owner != type && reader.has(key)) {
      reader.accept(key);
      reader.error(key, "'" + std::string(key) + "' does not go with '" + action_name(type) + "'");
      ok = false;
    }
  }
  return ok;
}

/// turn: counts (required) over over_s, ending within the run.
bool read_turn(TableReader& reader, Action& action, const ParseContext& context) {
  const auto counts = reader.integer("counts", ranges::kEncoderCounts, Need::kRequired);
  bool ok = counts.has_value();
  if (counts) action.counts = *counts;
  if (reader.has("over_s")) {
    const auto over = reader.number("over_s", ranges::kTimeS);
    if (over) action.over = to_time(*over);
    ok = ok && over.has_value();
  }
  check_end(reader, context, reader.has("over_s") ? "over_s" : "time_s", action.time + action.over, "the turn ends");
  return ok;
}

/// click: held for hold_ms, released within the run.
bool read_click(TableReader& reader, Action& action, const ParseContext& context) {
  bool ok = true;
  if (reader.has("hold_ms")) {
    const auto hold = reader.number("hold_ms", ranges::kTimeMs);
    if (hold) action.hold = to_time(*hold / 1000);
    ok = hold.has_value();
  }
  check_end(reader, context, reader.has("hold_ms") ? "hold_ms" : "time_s", action.time + action.hold,
            "the click releases");
  return ok;
}

/// serial file = "path": its bytes (reported when it cannot be read).
bool read_serial_file(TableReader& reader, Action& action, const ParseContext& context, const std::string& file) {
  action.serial_file = context.resolve(file);
  std::error_code error;
  std::ifstream in;
  if (std::filesystem::is_regular_file(action.serial_file, error)) in.open(action.serial_file, std::ios::binary);
  if (!in.is_open()) {
    reader.error("file", "serial file not found: " + action.serial_file);
    return false;
  }
  std::ostringstream bytes;
  bytes << in.rdbuf();
  action.serial_bytes = bytes.str();
  return true;
}

/// serial: text = "…" or file = "path", one of them.
bool read_serial(TableReader& reader, Action& action, const ParseContext& context) {
  const auto text = reader.string("text");
  const auto file = reader.string("file");
  if (text && file) {
    reader.error("file", "'serial' takes 'text' or 'file', not both");
    return false;
  }
  if (text) {
    action.serial_bytes = *text;
    return true;
  }
  if (file) return read_serial_file(reader, action, context, *file);
  if (!reader.has("text") && !reader.has("file"))
    reader.reporter().error(reader.line(), "'serial' needs 'text' or 'file'");
  return false;
}

bool read_details(TableReader& reader, Action& action, ParseContext& context) {
  bool ok = refuse_other_action_keys(reader, action.type);
  switch (action.type) {
    case ActionType::kTurn: return read_turn(reader, action, context) && ok;
    case ActionType::kClick: return read_click(reader, action, context) && ok;
    case ActionType::kSet: {
      const auto position = reader.number("position", NumberRange{0, 1, false, ""}, Need::kRequired);
      if (position) action.position = *position;
      return position.has_value() && ok;
    }
    case ActionType::kSerial: return read_serial(reader, action, context) && ok;
    case ActionType::kPress:
    case ActionType::kRelease: break;
  }
  return ok;
}

void read_action(const toml::table& table, ParseContext& context) {
  TableReader reader(table, "[[at]]", context.reporter);
  Action action;
  action.line = reader.line();
  bool ok = true;
  if (const auto time = reader.number("time_s", ranges::kTimeS, Need::kRequired)) {
    if (context.duration_valid && to_time(*time) > context.scenario.duration) {
      reader.error("time_s", "'time_s' = " + format_number(*time) + " is after the end of the run (duration_s = " +
                                 format_number(to_seconds(context.scenario.duration)) + ")");
      ok = false;
    } else {
      action.time = to_time(*time);
    }
  } else {
    ok = false;
  }

  const char* chosen = nullptr;
  for (const auto& [name, type] : kActions) {
    if (!reader.has(name)) continue;
    if (chosen != nullptr) {
      reader.accept(name);
      reader.error(name,
                   std::string("an [[at]] entry takes one action, but has both '") + chosen + "' and '" + name + "'");
      return;
    }
    chosen = name;
    action.type = type;
  }
  if (chosen == nullptr) {
    context.reporter.error(reader.line(),
                           "an [[at]] entry needs one action: turn, press, release, click, set or serial");
    return;
  }
  ok = read_target(reader, action, context) && ok;
  ok = read_details(reader, action, context) && ok;
  reader.finish();
  if (ok) context.scenario.timeline.push_back(std::move(action));
}

/// An encoder's count is its start plus every turn: the sum must stay well inside int64.
void check_encoder_totals(ParseContext& context) {
  constexpr int64_t kLimit = int64_t{1} << 62;
  std::map<std::string, int64_t> travel;  // |start| + Σ|counts| per encoder, at most kLimit
  for (const Action& action : context.scenario.timeline) {
    if (action.type != ActionType::kTurn) continue;
    const DeviceConfig* device = context.scenario.device(action.target);
    auto [entry, fresh] = travel.emplace(action.target, 0);
    const EncoderConfig* encoder = device != nullptr ? device->settings_as<EncoderConfig>() : nullptr;
    if (fresh && encoder != nullptr)
      entry->second = encoder->start_count < 0 ? -encoder->start_count : encoder->start_count;
    const int64_t counts = action.counts < 0 ? -action.counts : action.counts;  // within ±10^12
    if (entry->second <= kLimit - counts) {
      entry->second += counts;
    } else if (entry->second != kLimit + 1) {
      context.reporter.error(action.line, "encoder '" + action.target + "' would turn more than " +
                                              readable_integer(kLimit) + " counts in all; split the run");
      entry->second = kLimit + 1;  // reported once
    }
  }
}

}  // namespace

void read_timeline(TableReader& top, ParseContext& context) {
  for_each_table(top, "at", [&](const toml::table& table) { read_action(table, context); });
  check_encoder_totals(context);
}

}  // namespace stepdance::sim::scenario
