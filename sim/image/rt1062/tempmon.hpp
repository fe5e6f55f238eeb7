// TEMPMON (the die temperature monitor, RM chapter 16, registers §16.5): TEMPSENSE0..2, a part
// of the analog window at 0x400D8000 (offsets 0x180, 0x190 and 0x290, each with SET/CLR/TOG).
#pragma once

#include <array>
#include <cstdint>

#include "image/rt1062/analog_window.hpp"

namespace stepdance::sim::image::rt1062 {

/// The die sits at 25 °C, so a measurement reads ROOM_COUNT of the ANA1 fuse (OCOTP) and the
/// alarms (high/low IRQ 63, panic IRQ 64) never fire: they are not modelled. A measurement
/// (MEASURE_TEMP with POWER_DOWN clear) finishes at once — the RM gives no measurement time —
/// setting FINISHED (TEMPSENSE0 bit 2) and TEMP_CNT (bits 19:8).
class Tempmon : public WindowPart {
 public:
  explicit Tempmon(uint32_t ana1_fuse);
  const char* part_name() const override { return "TEMPMON"; }
  bool covers(uint32_t offset) const override;
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

 private:
  int index(uint32_t offset) const;
  uint32_t sense0() const;
  uint32_t room_count_;
  std::array<uint32_t, 3> values_{0x00000001u, 0x00000001u, 0x00000000u};  // RM §16.5.1–3 resets
};

}  // namespace stepdance::sim::image::rt1062
