// One memory-mapped block of the i.MX RT1062 as an emulated firmware image sees it.
#pragma once

#include <cstdint>

namespace stepdance::sim::image {

/// How a register access ended.
enum class Access : uint8_t {
  kOk,          ///< done; a read's value is set
  kUnmodelled,  ///< no model for this register: the run stops, naming address, PC and symbol
  kBusError,    ///< the chip answers with a bus fault (the firmware's BusFault handler runs)
};

/// The CCM clock gate a block needs (CCM_CCGRn, 2-bit field CGm; reference manual 14.7.21–14.7.28).
/// `ccgr` < 0: the block is always clocked (core peripherals, CCM itself, IOMUXC_SNVS, …).
struct ClockGate {
  int8_t ccgr = -1;
  int8_t field = 0;
};

/// A peripheral block: a name, an address window and its registers. Offsets are from base();
/// accesses are 1, 2 or 4 bytes wide and never cross a 32-bit word (the bus splits them).
/// Called on the simulator's thread only, at the simulated time the ChipContext reports.
class Peripheral {
 public:
  virtual ~Peripheral() = default;
  /// The reference manual's name of the block, e.g. "GPIO2", "FLEXIO3", "USB1".
  virtual const char* name() const = 0;
  virtual uint32_t base() const = 0;
  virtual uint32_t size_bytes() const = 0;
  /// The gate that must be on for an access; an access while it is off is a bus error (as on the
  /// chip: reference manual 14.5 "clock gating"), reported by the bus with the gate named.
  virtual ClockGate gate() const { return {}; }
  /// Reads `bytes` (1, 2 or 4) at `offset` into `value` (zero-extended).
  virtual Access read(uint32_t offset, uint8_t bytes, uint32_t& value) = 0;
  /// Writes the low `bytes` of `value` at `offset`.
  virtual Access write(uint32_t offset, uint8_t bytes, uint32_t value) = 0;
};

}  // namespace stepdance::sim::image
