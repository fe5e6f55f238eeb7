// FlexSPI1/FlexSPI2 (RM chapter 27, registers §27.7) as far as Teensyduino 1.59's startup uses
// them on the Teensy 4.1: configure_external_ram probes FlexSPI2 for PSRAM (and reads a few of
// FlexSPI1's settings). The simulated board has no PSRAM.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// FLEXSPI`number` (1 at 0x402A8000, gate CCGR6 CG5; 2 at 0x402A4000, gate CCGR7 CG1; RM table
/// 2-2, §14.7.27/28). Registers 0x000..0x2FC are stored as written, with: MCR0.SWRESET clearing
/// at once, INTR write-1-to-clear, STS0 reading idle (SEQIDLE | ARBIDLE), RFDRn reading all ones
/// (no memory on the chip selects: the data pads' pull-ups). An IP command (IPCMD.TRG) completes
/// at once (INTR IPCMDDONE, and IPRXWA for a read) on FlexSPI2; on FlexSPI1 (the boot flash:
/// programming, erasing) it is refused as unmodelled. Memory-mapped (AHB) accesses to the
/// flash are the CPU's memory map, not this block.
class FlexSpi : public Peripheral {
 public:
  explicit FlexSpi(unsigned number);
  const char* name() const override { return number_ == 1 ? "FLEXSPI" : "FLEXSPI2"; }
  uint32_t base() const override { return number_ == 1 ? 0x402A8000u : 0x402A4000u; }
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return number_ == 1 ? ClockGate{6, 5} : ClockGate{7, 1}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  unsigned number_;
  std::array<uint32_t, 0x300u / 4u> regs_{};
};

}  // namespace stepdance::sim::image::rt1062
