// IOMUXC_GPR (RM §11.4): the general-purpose registers GPR0..GPR34, of which the chip models
// use GPR14/16/17 (FlexRAM: TCM sizes, bank configuration) and GPR26..29 (GPIO1..4 or fast
// GPIO6..9 per pad).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// IOMUXC_GPR at 0x400AC000. Every GPR is stored as written (read/write, RM §11.4). Reset
/// values: all 0 except GPR16 = 0x00200003 (CM7_INIT_VTOR at the boot ROM, ITCM and DTCM on,
/// bank configuration from the fuses) — from memory of RM §11.4.17, not checked in this session.
/// Always clocked.
class IomuxcGpr : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x400AC000u;  // RM table 2-2
  static constexpr unsigned kCount = 35;          // GPR0..GPR34

  IomuxcGpr();
  const char* name() const override { return "IOMUXC_GPR"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return 0x4000u; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  uint32_t gpr(unsigned index) const { return values_[index]; }
  /// GPR26..29 bit `bit` set: pad of GPIO`port` (1..4) bit is driven by fast GPIO`port+5`.
  bool fast_gpio_selected(unsigned port, unsigned bit) const { return (values_[25 + port] >> bit) & 1u; }
  /// GPR17 FLEXRAM_BANK_CFG: 2 bits per 32 KB bank (00 off, 01 OCRAM, 10 DTCM, 11 ITCM), used
  /// when GPR16 FLEXRAM_BANK_CFG_SEL (bit 2) is 1 (RM §11.4.17, §11.4.18, §31.4 FlexRAM).
  uint32_t flexram_bank_config() const { return values_[17]; }
  bool flexram_config_from_gpr() const { return (values_[16] >> 2) & 1u; }
  /// GPR14 CM7_CFGITCMSZ (bits 19:16) and CM7_CFGDTCMSZ (bits 23:20) as bytes: code 0 = 0,
  /// 3..15 = 2^(code + 9) bytes (3 = 4 KB … 10 = 512 KB); 1 and 2 are reserved (0 here).
  uint32_t itcm_size_bytes() const { return tcm_bytes((values_[14] >> 16) & 0xFu); }
  uint32_t dtcm_size_bytes() const { return tcm_bytes((values_[14] >> 20) & 0xFu); }
  /// Adds a function called with the GPR's index after any write to it (the GPIO pads follow
  /// 26..29; the CPU helper may follow 14/16/17 for FlexRAM).
  void add_change_listener(std::function<void(unsigned index)> listener) { on_change_.push_back(std::move(listener)); }

 private:
  static uint32_t tcm_bytes(uint32_t code) { return code >= 3 && code <= 15 ? 1u << (code + 9u) : 0u; }

  std::array<uint32_t, kCount> values_{};
  std::vector<std::function<void(unsigned)>> on_change_;
};

}  // namespace stepdance::sim::image::rt1062
