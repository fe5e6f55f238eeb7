// What a peripheral model may ask of the emulated chip around it: time, interrupts, memory.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {
class Scheduler;
}

namespace stepdance::sim::image {

/// Implemented by the image board; handed to every peripheral model at construction.
/// All calls run on the simulator's thread: from a register access (inside the CPU's run) or
/// from a scheduler event (between runs).
class ChipContext {
 public:
  virtual ~ChipContext() = default;
  /// Simulated time now: the retiring instruction's time inside a register access, the event's
  /// time inside a scheduler event (ns since the simulation began).
  virtual SimTime now_ns() const = 0;
  /// Core clock cycles retired since reset (one instruction = one cycle; docs/simulator.md).
  virtual uint64_t cycles() const = 0;
  /// The core clock the image has set (ARM_PLL and CCM dividers), in Hz.
  virtual uint32_t core_clock_hz() const = 0;
  /// The simulator's event queue: a model schedules its own timed events here (timer expiries,
  /// conversions done). The CPU never runs past the next queued event.
  virtual Scheduler& scheduler() = 0;
  /// Drives the level of interrupt line `irq` (0..159, reference manual 4.3 table 4-2). A high
  /// level keeps the interrupt pending until the line falls; a rising level pends it.
  virtual void set_irq_level(unsigned irq, bool high) = 0;
  /// Ends the CPU's current run after the access in progress: call after any change the rest
  /// of the simulation must see at this time (a pin toggled, a byte sent).
  virtual void stop_cpu_run() = 0;
  /// Bus-master access to the image's memory (DMA, the USB controller's queue heads). False if
  /// any byte is outside mapped RAM or flash.
  virtual bool read_memory(uint32_t address, void* data, size_t bytes) = 0;
  virtual bool write_memory(uint32_t address, const void* data, size_t bytes) = 0;
};

}  // namespace stepdance::sim::image
