// The registry of machine kinds: the built-in ones in the order messages list them, then any
// registered at run time (a test's own kind).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kinds/machine_kind.hpp"
#include "kinds/scoped_kind.hpp"

namespace stepdance::sim {

/// Every machine kind, built-in first. Context: host, single thread.
const std::vector<const MachineKind*>& machine_kinds();
/// The kind with this `type` name, or null.
const MachineKind* find_machine_kind(std::string_view name);
/// "\"corexy_plotter\", \"cartesian\" or \"polar\"", for the message of an unknown type.
std::string machine_kind_names();

/// The built-in kinds, in order (kinds/builtin_machine_kinds.cpp: one line per kind).
std::vector<const MachineKind*> builtin_machine_kinds();

/// The run-time side of the list: a test adds its own kind with a ScopedKind<MachineRegistry>.
struct MachineRegistry {
  using Kind = MachineKind;
  static void add(const MachineKind& kind);
  static void remove(const MachineKind& kind);
};

}  // namespace stepdance::sim
