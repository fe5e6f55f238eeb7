// Scenario vocabulary: module, connector and device names, and what each module has.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "scenario/scenario.hpp"

namespace stepdance::sim::scenario {

/// "driver" or "basic".
std::string_view module_name(Module module);
/// What the scenario reader knows of one kind of input device.
struct DeviceKind {
  DeviceType type;
  std::string_view name;          ///< the `type` value in the file, e.g. "encoder"
  std::string_view with_article;  ///< for messages, e.g. "an encoder"
  std::string_view connectors;    ///< the connectors it fits, for messages, e.g. "ENC1 or ENC2"
  bool (*fits)(Connector connector);
};
/// Every device kind, in the order messages list them.
struct DeviceKindList {
  const DeviceKind* first;
  size_t size;
  const DeviceKind* begin() const { return first; }
  const DeviceKind* end() const { return first + size; }
  const DeviceKind& front() const { return *first; }
};
DeviceKindList device_kinds();
/// The row of a device type.
const DeviceKind& device_kind(DeviceType type);

/// "encoder", "potentiometer", "button", "limit_switch", "pendulum".
std::string_view device_type_name(DeviceType type);
/// "an encoder", "a potentiometer", "a button", "a limit switch".
std::string_view device_with_article(DeviceType type);

/// The connector with this silkscreen name, if any.
std::optional<Connector> parse_connector(std::string_view name);
/// Whether a module has the connector (the Basic Module has no limit headers).
bool module_has_connector(Module module, Connector connector);
/// Whether a device type can sit on the connector.
bool device_fits_connector(DeviceType type, Connector connector);
/// The connectors a device type can use, for messages, e.g. "ENC1 or ENC2".
std::string_view connectors_for(DeviceType type);

/// Whether a module has input and output port `port` (Driver: A..D; Basic: A).
bool module_has_port(Module module, char port);

/// "board:rest" split at its only ':'; nothing if the form is wrong or a part is empty.
struct SplitRef {
  std::string board;
  std::string rest;
};
std::optional<SplitRef> split_ref(std::string_view text);

}  // namespace stepdance::sim::scenario
