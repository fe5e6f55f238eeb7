// The chip's peripheral address space: which block answers an address, and whether it is clocked.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image {

/// Why an access did not reach a register model.
struct BusRefusal {
  enum class Kind : uint8_t { kNone, kNoBlock, kUnmodelled, kGateOff, kBusError };
  Kind kind = Kind::kNone;
  uint32_t address = 0;
  bool is_write = false;
  uint8_t bytes = 0;
  std::string block;  ///< the block's name ("" when no block covers the address)
  ClockGate gate;     ///< for kGateOff: the gate that was off
  /// One line for a run report, e.g. "read of 4 bytes at 0x401F8004 (IOMUXC_GPR+0x4): no model".
  std::string describe() const;
};

/// Peripheral blocks by address. Blocks are added once, before the image runs, and must not
/// overlap; the bus does not own them. An access that no block covers, that a block does not
/// model, or that reaches a block whose clock gate is off is refused and described, never
/// answered with a made-up value.
class PeripheralBus {
 public:
  /// Tells whether a clock gate is on (the CCM model answers; until one is set, all are on).
  using GateQuery = std::function<bool(ClockGate)>;

  /// Adds `block`. False (and nothing added) if its window overlaps one already added.
  bool add(Peripheral& block);
  void set_gate_query(GateQuery query) { gate_on_ = std::move(query); }

  /// The block covering `address`, or null.
  Peripheral* find(uint32_t address) const;
  /// Reads or writes `bytes` (1, 2 or 4, naturally aligned) at `address`. On refusal returns
  /// false and fills `refusal`.
  bool read(uint32_t address, uint8_t bytes, uint32_t& value, BusRefusal& refusal) const;
  bool write(uint32_t address, uint8_t bytes, uint32_t value, BusRefusal& refusal) const;
  const std::vector<Peripheral*>& blocks() const { return blocks_; }

 private:
  Peripheral* admit(uint32_t address, bool is_write, uint8_t bytes, BusRefusal& refusal) const;

  std::vector<Peripheral*> blocks_;  ///< sorted by base address
  GateQuery gate_on_;
};

}  // namespace stepdance::sim::image
