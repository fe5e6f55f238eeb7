// The device kind registry: the built-in list plus kinds registered at run time.
#include "kinds/device_registry.hpp"

#include <algorithm>

#include "kinds/kind_registry.hpp"

namespace stepdance::sim {
namespace {

KindRegistry<DeviceKind>& registry() {
  static KindRegistry<DeviceKind> kinds(builtin_device_kinds());
  return kinds;
}

}  // namespace

bool DeviceKind::has_key(std::string_view key) const {
  return std::any_of(keys.begin(), keys.end(), [key](const DeviceKey& own) { return own.name == key; });
}

const std::vector<const DeviceKind*>& device_kinds() { return registry().all(); }

const DeviceKind* find_device_kind(std::string_view name) { return registry().find(name); }

const DeviceKind* first_kind_taking(scenario::ActionType type) {
  for (const DeviceKind* kind : device_kinds()) {
    if (kind->takes(type)) return kind;
  }
  return nullptr;
}

std::string device_kind_names() { return registry().names(); }

void DeviceRegistry::add(const DeviceKind& kind) { registry().add(kind); }

void DeviceRegistry::remove(const DeviceKind& kind) { registry().remove(kind); }

}  // namespace stepdance::sim
