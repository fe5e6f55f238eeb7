// One row per device kind: everything the simulator knows of a kind of [[device]] — its name,
// its scenario keys, how it is read, how its model is built and plugged in, and its page control.
#pragma once

#include <any>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kinds/sim_device.hpp"
#include "scenario/parse_context.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// How the live view's page lets a user act on a device: the control it draws and its range.
/// The page reads this descriptor only; what a control does is the kind's timeline actions
/// (DeviceKind::actions) at the device's name.
struct PageControl {
  enum class Type {
    kNone,            ///< nothing to act on (the device follows the machine or its own script)
    kKnob,            ///< an endless knob turned by `step` counts a detent (`turn`)
    kSlider,          ///< a position in [low, high] (`set`)
    kButton,          ///< a momentary button (`press`, `release`, `click`)
    kKnobWithButton,  ///< a knob whose shaft is also a button (`turn`, `press`, `release`, `click`)
    kScreen,          ///< a picture of a display to show, nothing to act on
  };
  Type type = Type::kNone;
  double low = 0;
  double high = 0;
  double step = 1;
  const char* unit = "";
};

/// One of a kind's own keys, for the "does not apply" rule and for the page: its name, its type
/// and, for a number, its range (the kind's reader checks the value with the same constants).
struct DeviceKey {
  enum class Type { kNumber, kInteger, kBoolean, kString, kList };
  const char* name;
  Type type;
  double low = 0;  ///< numbers: the range, inclusive (a time "within the run" has high = a day)
  double high = 0;
  const char* unit = "";
};

/// What a kind's reader works on: the [[device]] table, the scenario so far, and the device with
/// its common keys (name, board, connector) already read.
struct DeviceReading {
  scenario::TableReader& reader;
  const scenario::ParseContext& context;
  scenario::DeviceConfig& device;
  /// Claims a second connector of the device (a five-bar arm's left encoder), reported at `key`
  /// if another device uses it. Returns false if it is taken.
  std::function<bool(std::string_view key, scenario::Connector connector)> claim_connector;
};

/// Which timeline actions a kind takes, as bits of 1 << ActionType.
using ActionSet = uint32_t;
constexpr ActionSet actions(std::initializer_list<scenario::ActionType> types) {
  ActionSet set = 0;
  for (scenario::ActionType type : types) set |= ActionSet{1} << static_cast<int>(type);
  return set;
}

/// A device kind. Register it with one line in kinds/builtin_device_kinds.cpp (or, in a test,
/// with a ScopedKind<DeviceRegistry>: kinds/device_registry.hpp); docs/architecture.md, "Where
/// things go", has the map.
struct DeviceKind {
  std::string_view name;          ///< the `type` value in the file, e.g. "encoder"
  std::string_view with_article;  ///< for messages, e.g. "an encoder"
  std::string_view connectors;    ///< the connectors it fits, for messages, e.g. "ENC1 or ENC2"
  bool (*fits)(scenario::Connector connector);
  /// The kind's own keys, in the order "does not apply" lists them.
  std::vector<DeviceKey> keys;
  /// Reads the kind's keys (each through the reader, which reports wrong types and ranges) and
  /// returns its settings (the kind's config struct, e.g. EncoderConfig).
  std::any (*read)(DeviceReading& reading);
  /// Builds the model from a device read by `read` and plugs it into the board.
  std::unique_ptr<SimDevice> (*build)(const scenario::DeviceConfig& device, DevicePlug& plug);
  /// The timeline actions it takes.
  ActionSet actions = 0;
  PageControl control;
  /// The files (in the output folder) the device writes at the end of the run, known before it
  /// is built; null for a kind that writes none.
  std::vector<std::string> (*output_names)(const scenario::DeviceConfig& device) = nullptr;
  /// The live view's part types the device gives (SimDevice::add_page_parts, kinds/page_part.hpp),
  /// e.g. "screens": declared in `hello` as the device's "parts", so that the page sets their
  /// drawing up before the first update. Empty for a kind with none.
  std::vector<std::string_view> page_parts = {};

  bool takes(scenario::ActionType type) const { return (actions >> static_cast<int>(type)) & 1; }
  bool has_key(std::string_view key) const;
};

}  // namespace stepdance::sim
