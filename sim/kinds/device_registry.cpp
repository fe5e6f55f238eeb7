// The device kind registry: the built-in list plus kinds registered at run time.
#include "kinds/device_registry.hpp"

#include <algorithm>

namespace stepdance::sim {
namespace {

std::vector<const DeviceKind*>& registry() {
  static std::vector<const DeviceKind*> kinds = builtin_device_kinds();
  return kinds;
}

}  // namespace

bool DeviceKind::has_key(std::string_view key) const {
  return std::any_of(keys.begin(), keys.end(), [key](const DeviceKey& own) { return own.name == key; });
}

const std::vector<const DeviceKind*>& device_kinds() { return registry(); }

const DeviceKind* find_device_kind(std::string_view name) {
  for (const DeviceKind* kind : device_kinds()) {
    if (kind->name == name) return kind;
  }
  return nullptr;
}

const DeviceKind* first_kind_taking(scenario::ActionType type) {
  for (const DeviceKind* kind : device_kinds()) {
    if (kind->takes(type)) return kind;
  }
  return nullptr;
}

std::string device_kind_names() {
  std::string text;
  const std::vector<const DeviceKind*>& kinds = device_kinds();
  for (size_t i = 0; i < kinds.size(); ++i) {
    if (i > 0) text += i + 1 == kinds.size() ? " or " : ", ";
    text += "\"" + std::string(kinds[i]->name) + "\"";
  }
  return text;
}

ScopedDeviceKind::ScopedDeviceKind(const DeviceKind& kind) : kind_(kind) { registry().push_back(&kind); }

ScopedDeviceKind::~ScopedDeviceKind() {
  std::vector<const DeviceKind*>& kinds = registry();
  kinds.erase(std::remove(kinds.begin(), kinds.end(), &kind_), kinds.end());
}

}  // namespace stepdance::sim
