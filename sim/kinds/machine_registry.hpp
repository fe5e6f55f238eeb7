// The registry of machine kinds: the built-in ones in the order messages list them, then any
// registered at run time (a test's own kind).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kinds/machine_kind.hpp"

namespace stepdance::sim {

/// Every machine kind, built-in first. Context: host, single thread.
const std::vector<const MachineKind*>& machine_kinds();
/// The kind with this `type` name, or null.
const MachineKind* find_machine_kind(std::string_view name);
/// "\"corexy_plotter\", \"cartesian\" or \"polar\"", for the message of an unknown type.
std::string machine_kind_names();

/// The built-in kinds, in order (kinds/builtin_machine_kinds.cpp: one line per kind).
std::vector<const MachineKind*> builtin_machine_kinds();

/// Adds a kind for as long as it lives (a test's kind); the kind must outlive it.
class ScopedMachineKind {
 public:
  explicit ScopedMachineKind(const MachineKind& kind);
  ~ScopedMachineKind();
  ScopedMachineKind(const ScopedMachineKind&) = delete;
  ScopedMachineKind& operator=(const ScopedMachineKind&) = delete;

 private:
  const MachineKind& kind_;
};

}  // namespace stepdance::sim
