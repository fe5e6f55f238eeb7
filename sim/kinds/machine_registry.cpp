// The machine kind registry: the built-in list plus kinds registered at run time.
#include "kinds/machine_registry.hpp"

#include "kinds/kind_registry.hpp"

namespace stepdance::sim {
namespace {

KindRegistry<MachineKind>& registry() {
  static KindRegistry<MachineKind> kinds(builtin_machine_kinds());
  return kinds;
}

}  // namespace

const std::vector<const MachineKind*>& machine_kinds() { return registry().all(); }

const MachineKind* find_machine_kind(std::string_view name) { return registry().find(name); }

std::string machine_kind_names() { return registry().names(); }

void MachineRegistry::add(const MachineKind& kind) { registry().add(kind); }

void MachineRegistry::remove(const MachineKind& kind) { registry().remove(kind); }

}  // namespace stepdance::sim
