// The registry of device kinds: the built-in ones in the order messages list them, then any
// registered at run time (a test's own kind).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kinds/device_kind.hpp"
#include "kinds/scoped_kind.hpp"

namespace stepdance::sim {

/// Every device kind, built-in first. Context: host, single thread.
const std::vector<const DeviceKind*>& device_kinds();
/// The kind with this `type` name, or null.
const DeviceKind* find_device_kind(std::string_view name);
/// The first kind that takes the action (the one messages name: `turn` needs "an encoder").
const DeviceKind* first_kind_taking(scenario::ActionType type);
/// "\"encoder\", \"potentiometer\", … or \"twist\"", for the message of an unknown type.
std::string device_kind_names();

/// The built-in kinds, in order (kinds/builtin_device_kinds.cpp: one line per kind).
std::vector<const DeviceKind*> builtin_device_kinds();

/// The run-time side of the list: a test adds its own kind with a ScopedKind<DeviceRegistry>.
struct DeviceRegistry {
  using Kind = DeviceKind;
  static void add(const DeviceKind& kind);
  static void remove(const DeviceKind& kind);
};

}  // namespace stepdance::sim
