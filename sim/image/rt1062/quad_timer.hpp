// TMR1..4 (the quad timers, RM chapter 54, registers §54.9) as far as Teensyduino's pwm_init and
// analogWrite configure them: configuration storage, no counting.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// TMR`number` (1..4) at 0x401DC000 + 0x4000 (number − 1); gates CCGR6 CG13/CG14/CG15/CG8
/// (RM §14.7.27). Four channels of 16-bit registers 0x20 apart (COMP1, COMP2, CAPT, LOAD, HOLD,
/// CNTR, CTRL, SCTRL, CMPLD1, CMPLD2, CSCTRL, FILT, DMA; ENBL at 0x1E of channel 0), all stored
/// as written (reset values 0, ENBL 0x000F). The counters do not count and their outputs do not
/// reach the pads: while a channel's CTRL.CM ≠ 0 (counting), reads of its CAPT, HOLD, CNTR,
/// SCTRL and CSCTRL (which would show the count and its flags) are refused as unmodelled, and
/// so are writes that enable its interrupts (SCTRL TCFIE/TOFIE/IEFIE, CSCTRL TCF1EN/TCF2EN).
class QuadTimer : public Peripheral {
 public:
  explicit QuadTimer(unsigned number);
  const char* name() const override { return kNames[number_]; }
  uint32_t base() const override { return 0x401DC000u + 0x4000u * (number_ - 1u); }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override;
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  static constexpr const char* kNames[5] = {"", "TMR1", "TMR2", "TMR3", "TMR4"};
  static constexpr uint32_t kSize = 0x80u;                                                  // 4 channels × 0x20
  bool counting(unsigned channel) const { return (half_[channel * 16u + 6u] >> 13) != 0; }  // CTRL.CM
  bool readable(uint32_t half_index) const;
  bool writable(uint32_t half_index, uint16_t value) const;

  unsigned number_;
  std::array<uint16_t, kSize / 2u> half_{};
};

}  // namespace stepdance::sim::image::rt1062
