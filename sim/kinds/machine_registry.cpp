// The machine kind registry: the built-in list plus kinds registered at run time.
#include "kinds/machine_registry.hpp"

#include <algorithm>

namespace stepdance::sim {
namespace {

std::vector<const MachineKind*>& registry() {
  static std::vector<const MachineKind*> kinds = builtin_machine_kinds();
  return kinds;
}

}  // namespace

const std::vector<const MachineKind*>& machine_kinds() { return registry(); }

const MachineKind* find_machine_kind(std::string_view name) {
  for (const MachineKind* kind : machine_kinds()) {
    if (kind->name == name) return kind;
  }
  return nullptr;
}

std::string machine_kind_names() {
  std::string text;
  const std::vector<const MachineKind*>& kinds = machine_kinds();
  for (size_t i = 0; i < kinds.size(); ++i) {
    if (i > 0) text += i + 1 == kinds.size() ? " or " : ", ";
    text += "\"" + std::string(kinds[i]->name) + "\"";
  }
  return text;
}

ScopedMachineKind::ScopedMachineKind(const MachineKind& kind) : kind_(kind) { registry().push_back(&kind); }

ScopedMachineKind::~ScopedMachineKind() {
  std::vector<const MachineKind*>& kinds = registry();
  kinds.erase(std::remove(kinds.begin(), kinds.end(), &kind_), kinds.end());
}

}  // namespace stepdance::sim
