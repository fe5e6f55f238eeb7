// IOMUXC (RM chapter 11, registers §11.7): each pad's mux (SW_MUX_CTL_PAD), its electrical
// settings (SW_PAD_CTL_PAD) and the input (daisy) selects.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/chip/peripheral.hpp"
#include "image/rt1062/pads.hpp"

namespace stepdance::sim::image::rt1062 {

/// The IOMUXC at 0x401F8000. Pad registers hold their fields (reserved bits read 0); the daisy
/// selects (offsets 0x3F4..0x78C) are stored for the models that route inputs. Offsets
/// 0x000..0x010 (reserved in RM §11.7's map) and past 0x78C are unmodelled. Always clocked (IOMUXC has no gate the
/// firmware turns off: CCGR4 CG1 "iomuxc" is on at reset and Teensyduino never clears it; not enforced).
class Iomuxc : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x401F8000u;  // RM table 2-2
  static constexpr uint32_t kMuxAltGpio = 5;      // ALT5 = GPIO on every GPIO pad (RM table 10-1)
  static constexpr uint32_t kMuxSion = 1u << 4;   // SION: input path on whatever the ALT

  Iomuxc();
  const char* name() const override { return "IOMUXC"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return 0x4000u; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// A pad's SW_MUX_CTL_PAD (MUX_MODE bits 3:0, SION bit 4) and SW_PAD_CTL_PAD values.
  uint32_t pad_mux(int pad) const { return mux_[static_cast<size_t>(pad)]; }
  uint32_t pad_ctl(int pad) const { return ctl_[static_cast<size_t>(pad)]; }
  /// True if the pad's mux selects its GPIO (ALT5).
  bool pad_is_gpio(int pad) const { return (pad_mux(pad) & 0xFu) == kMuxAltGpio; }
  /// A daisy select register's value (`offset` from the IOMUXC base, 0x3F4..0x78C).
  uint32_t select_input(uint32_t offset) const;
  /// Adds a function called with the pad index after a write changes a pad's mux or pad control.
  void add_pad_listener(std::function<void(int pad)> listener) { on_pad_.push_back(std::move(listener)); }

 private:
  bool write_pad(uint32_t offset, uint8_t bytes, uint32_t value);

  std::array<uint32_t, kPadCount> mux_{};
  std::array<uint32_t, kPadCount> ctl_{};
  std::array<uint32_t, (0x790u - 0x3F4u) / 4u> selects_{};
  std::vector<std::function<void(int)>> on_pad_;
};

}  // namespace stepdance::sim::image::rt1062
