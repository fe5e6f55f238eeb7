// A host-side model of the i.MX RT1062 registers the Teensy backend touches, for tests only.
//
// The backend is compiled for the host with STEPDANCE_TEENSY_REGISTER_MODEL defined, so every
// reg32/16/8 access, every DSB and every PRIMASK/BASEPRI/IPSR access lands here. The model is a
// sparse memory map plus a log of every access, stamped with the model time and the interrupt
// masks in force; tests play the hardware with read and write hooks on single addresses.
#pragma once

#include <stdint.h>

#include <functional>
#include <vector>

namespace teensy_model {

/// One logged register access.
struct Access {
  enum Kind { kRead, kWrite, kSpecialWrite } kind;
  uint32_t address;     ///< register address (0 for special registers)
  uint32_t value;       ///< value read or written
  const char* special;  ///< "primask" / "basepri" for kSpecialWrite, else nullptr
  uint32_t primask;     ///< PRIMASK when the access happened
  uint32_t basepri;     ///< BASEPRI when the access happened
  uint64_t cycles;      ///< model time in core cycles
};

/// Core clock of the model (Teensyduino's default 600 MHz) and its bus clock (150 MHz).
constexpr uint32_t kCoreHz = 600000000u;
constexpr uint32_t kBusHz = 150000000u;

/// Clears memory, log, hooks, vectors and time; PRIMASK = BASEPRI = IPSR = 0.
void reset();
/// Reads/writes the model's memory without logging or hooks (the test playing the hardware).
uint32_t peek(uint32_t address, unsigned bytes = 4);
void poke(uint32_t address, uint32_t value, unsigned bytes = 4);
/// Every access since reset(), in order.
const std::vector<Access>& log();

/// Called on a write to `address`: gets the stored and the written value, returns what to store.
using WriteHook = std::function<uint32_t(uint32_t stored, uint32_t written)>;
/// Called on a read of `address`: gets the stored value, returns what the read sees.
using ReadHook = std::function<uint32_t(uint32_t stored)>;
void on_write(uint32_t address, WriteHook hook);
void on_read(uint32_t address, ReadHook hook);
/// Makes `address` write-one-to-clear (status flag registers).
void write_one_to_clear(uint32_t address);

/// Model time in core cycles; every DWT_CYCCNT read advances it by 10 cycles.
uint64_t now_cycles();
void advance_cycles(uint64_t cycles);

/// The handler attachInterruptVector() set for `irq` (nullptr if none).
void (*vector(unsigned irq))();
/// Runs `irq`'s handler as an exception: IPSR = 16 + irq while it runs.
void run_isr(unsigned irq);
/// Current PRIMASK and BASEPRI.
uint32_t primask();
uint32_t basepri();

}  // namespace teensy_model
