// DCDC (the on-chip core-voltage converter, RM chapter 18, registers §18.6) and the PMU's
// regulator registers (RM §13.4) as far as the clock change and USB start touch them.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/peripheral.hpp"
#include "image/rt1062/analog_window.hpp"

namespace stepdance::sim::image::rt1062 {

/// DCDC at 0x40080000: REG0..REG3. REG3 TRG (bits 4:0) sets the core voltage, 0.8 V + 25 mV × TRG;
/// REG0 STS_DC_OK (bit 31, read only) reads 1: the RM (§18.6.1) gives no settling time, so the
/// output is taken as settled at once. Gated by CCGR6 CG3 (RM §14.7.27, "dcdc").
class Dcdc : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x40080000u;  // RM table 2-2

  Dcdc();
  const char* name() const override { return "DCDC"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return ClockGate{6, 3}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;
  /// The core voltage REG3 TRG asks for, mV.
  uint32_t core_millivolts() const { return 800u + 25u * (values_[3] & 0x1Fu); }

 private:
  std::array<uint32_t, 4> values_{};
};

/// PMU_REG_1P1, REG_3P0, REG_2P5 and REG_CORE (window offsets 0x110..0x14C, with SET/CLR/TOG).
/// Plain storage: no regulator behaviour is modelled (PMU_MISC0..2 are CCM_ANALOG's MISC0..2).
class Pmu : public WindowPart {
 public:
  Pmu();
  const char* part_name() const override { return "PMU"; }
  bool covers(uint32_t offset) const override { return offset >= 0x110u && offset < 0x150u; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  std::array<uint32_t, 4> values_{};
};

}  // namespace stepdance::sim::image::rt1062
