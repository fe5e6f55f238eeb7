// Registers a kind (a device kind, a machine kind, a board) for as long as an object lives: how a
// test adds a kind of its own without editing the built-in lists.
#pragma once

namespace stepdance::sim {

/// `Registry` is a list of kinds: its `Kind` type and its static `add` and `remove` of one kind
/// (DeviceRegistry in kinds/device_registry.hpp, MachineRegistry, BoardRegistry). Adds the kind
/// when built and removes it when destroyed; the kind must outlive it. Context: host, single
/// thread.
template <typename Registry>
class ScopedKind {
 public:
  using Kind = typename Registry::Kind;

  explicit ScopedKind(const Kind& kind) : kind_(kind) { Registry::add(kind_); }
  ~ScopedKind() { Registry::remove(kind_); }
  ScopedKind(const ScopedKind&) = delete;
  ScopedKind& operator=(const ScopedKind&) = delete;

 private:
  const Kind& kind_;
};

}  // namespace stepdance::sim
