// CCM_ANALOG: the PLLs, their phase-fractional dividers (PFDs) and MISC0..2 (RM §14.8), a part
// of the analog window at 0x400D8000.
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "image/chip/chip_context.hpp"
#include "image/rt1062/analog_window.hpp"
#include "image/rt1062/register_bits.hpp"

namespace stepdance::sim::image::rt1062 {

/// The 24 MHz crystal oscillator every PLL multiplies (RM §14.3, "OSC24M").
constexpr uint32_t kOscillatorHz = 24000000u;

/// The PLLs by name (RM §14.8: PLL1 = ARM, PLL2 = SYS (528), PLL3 = USB1 (480), PLL4 = AUDIO,
/// PLL5 = VIDEO, PLL6 = ENET, PLL7 = USB2).
enum class Pll : uint8_t { kArm, kUsb1, kUsb2, kSys, kAudio, kVideo, kEnet };

/// PLL registers, PFDs and MISC0..2 with their SET/CLR/TOG aliases.
///
/// Locking: a PLL that is powered (and whose DIV_SELECT changes while powered) sets LOCK (bit 31)
/// a lock time later. The RM gives no lock times; these come from the i.MX RT1060 data sheet's
/// PLL tables (IMXRT1060CEC §4.1, "PLL's electrical characteristics"): ARM PLL 2250 reference
/// cycles, 480 (USB) PLLs 383, 528 and audio/video/ENET PLLs 11250 (cycles of the 24 MHz
/// reference). All calls on the simulator thread.
class CcmAnalog : public WindowPart {
 public:
  explicit CcmAnalog(ChipContext& context);

  const char* part_name() const override { return "CCM_ANALOG"; }
  bool covers(uint32_t offset) const override;
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// Called whenever a PLL's or PFD's output may have changed (a write, or a lock reached).
  void set_change_listener(std::function<void()> listener) { on_change_ = std::move(listener); }

  /// The PLL's output in Hz now: 0 when its output is disabled, powered down or not locked;
  /// the 24 MHz reference when bypassed. PLL_AUDIO/VIDEO/ENET report 0 (not modelled as clocks).
  uint32_t pll_hz(Pll pll) const;
  /// PFD `index` (0..3) of PLL2 (`pll` = kSys, PFD_528) or PLL3 (kUsb1, PFD_480), in Hz:
  /// PLL × 18 / PFDn_FRAC (RM §14.8.15/16), 0 when gated.
  uint32_t pfd_hz(Pll pll, unsigned index) const;
  /// The register's value now (as a read at `offset` from the window base returns it).
  uint32_t value_at(uint32_t offset) const;
  /// Puts PLL1 (ARM) at 792 MHz (DIV_SELECT 66) and PLL2 (SYS) at 528 MHz, both powered, enabled,
  /// not bypassed and locked since time 0, as the boot ROM leaves them (see
  /// ClockAndPinBlocks::apply_boot_rom_clocks).
  void apply_boot_rom_state();
  /// The time LOCK sets (or set) for `pll`, ns; -1 while it is powered down.
  SimTime lock_time_ns(Pll pll) const { return lock_at_ns_[static_cast<size_t>(pll)]; }

 private:
  struct Register {
    uint32_t offset;
    uint32_t reset;
    bool aliases;  // SET/CLR/TOG at +4/+8/+C
  };
  static const std::array<Register, 20> kRegisters;

  int find(uint32_t offset) const;
  void write_pll(Pll pll, uint32_t old_value, uint32_t new_value);
  bool powered(Pll pll, uint32_t value) const;
  bool locked(Pll pll) const;
  uint32_t pll_register(Pll pll) const;
  void changed();

  ChipContext& context_;
  std::array<uint32_t, 20> values_{};
  std::array<SimTime, 7> lock_at_ns_{};
  ModelEvent lock_event_;
  std::function<void()> on_change_;
};

}  // namespace stepdance::sim::image::rt1062
