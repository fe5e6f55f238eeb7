// The registry of device kinds: the built-in ones in the order messages list them, then any
// registered at run time (a test's own kind).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kinds/device_kind.hpp"

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

/// Adds a kind for as long as it lives (a test's kind); the kind must outlive it.
class ScopedDeviceKind {
 public:
  explicit ScopedDeviceKind(const DeviceKind& kind);
  ~ScopedDeviceKind();
  ScopedDeviceKind(const ScopedDeviceKind&) = delete;
  ScopedDeviceKind& operator=(const ScopedDeviceKind&) = delete;

 private:
  const DeviceKind& kind_;
};

}  // namespace stepdance::sim
