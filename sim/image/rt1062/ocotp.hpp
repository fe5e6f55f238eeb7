// OCOTP (On-Chip OTP controller, RM chapter 23, registers §23.6): the fuse shadow registers the
// firmware reads — the temperature sensor's calibration (ANA1), the MAC/serial number (MAC0/1),
// the boot configuration (CFG0..6) and LOCK.
#pragma once

#include <array>
#include <cstdint>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// OCOTP at 0x401F4000 (gate CCGR2 CG6, RM §14.7.23). Shadow registers read their fuse values
/// and ignore writes; the controller registers (CTRL, READ_CTRL, … for fuse reads and
/// programming) and all other shadows are unmodelled. The fuses are those of a simulated chip:
/// all 0 but ANA1 (kAna1, a temperature calibration: 25 °C at count 0x5C0, 105 °C at 0x4C0)
/// and MAC0 (the USB serial number's low 24 bits), which set_fuse changes.
class Ocotp : public Peripheral {
 public:
  /// ANA1: ROOM_COUNT bits 31:20, HOT_COUNT bits 19:8, HOT_TEMP (°C) bits 7:0 (RM §23.6.1.36).
  static constexpr uint32_t kAna1 = (0x5C0u << 20) | (0x4C0u << 8) | 105u;
  static constexpr uint32_t kShadowBase = 0x400u;  // HW_OCOTP_LOCK; shadow n at 0x400 + 0x10 n

  Ocotp();
  const char* name() const override { return "OCOTP"; }
  uint32_t base() const override { return 0x401F4000u; }  // RM table 2-2
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override { return ClockGate{2, 6}; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;
  /// Sets the fuse behind the shadow at `offset` (one of the modelled shadows). False otherwise.
  bool set_fuse(uint32_t offset, uint32_t value);

 private:
  int index(uint32_t offset) const;
  std::array<uint32_t, 12> fuses_{};
};

}  // namespace stepdance::sim::image::rt1062
