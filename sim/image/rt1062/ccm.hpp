// CCM (Clock Controller Module, RM chapter 14, registers §14.7): clock gates CCGR0..7, the core,
// IPG and PERCLK clock roots, and the divider handshake.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/rt1062/ccm_analog.hpp"

namespace stepdance::sim::image::rt1062 {

/// The clock roots the rest of the chip runs from, in Hz.
struct ClockRates {
  uint32_t core_hz = 0;    ///< AHB_CLK_ROOT = the Cortex-M7 core clock
  uint32_t ipg_hz = 0;     ///< IPG_CLK_ROOT (the peripheral bus)
  uint32_t perclk_hz = 0;  ///< PERCLK_CLK_ROOT (GPT, PIT)
};

/// The CCM at 0x400FC000. Registers keep what the firmware writes (the read-only CSR and CDHIPR
/// aside); clock roots follow CBCDR/CBCMR/CACRR/CCSR/CSCMR1 and the PLLs of CCM_ANALOG.
/// The divider/mux handshake (CDHIPR busy bits) completes at once: the RM (§14.7.20) states it
/// takes a few cycles of the slower clock and gives no figure. Always clocked (no gate).
class Ccm : public Peripheral {
 public:
  static constexpr uint32_t kBase = 0x400FC000u;  // RM table 2-2 / §14.7

  Ccm(ChipContext& context, CcmAnalog& analog);

  const char* name() const override { return "CCM"; }
  uint32_t base() const override { return kBase; }
  uint32_t size_bytes() const override { return 0x4000u; }
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  /// Whether a clock gate is on (CGn ≠ 00: on in run mode; RM §14.7.21). Wire into
  /// PeripheralBus::set_gate_query. Context: any.
  bool gate_on(ClockGate gate) const;
  /// The clock roots now.
  ClockRates rates() const;
  uint32_t core_clock_hz() const { return rates().core_hz; }
  uint32_t ipg_clock_hz() const { return rates().ipg_hz; }
  uint32_t perclk_hz() const { return rates().perclk_hz; }
  /// FLEXIO2_CLK_ROOT (which also clocks FlexIO3): CSCMR2 FLEXIO2_CLK_SEL through CS1CDR
  /// FLEXIO2_CLK_PRED and _PODF (RM §14.7.9, §14.7.11), Hz.
  uint32_t flexio2_clock_hz() const;
  /// Adds a function called with the new rates whenever any of them changes (the lead passes
  /// core_hz to ImageChip::set_core_clock_hz; the timers follow PERCLK). Called at once with the
  /// rates now when added.
  void add_rates_listener(std::function<void(const ClockRates&)> listener);
  /// Sets CBCDR IPG_PODF = 2 (÷3), the IPG divider the boot ROM leaves (see
  /// ClockAndPinBlocks::apply_boot_rom_clocks); the core's path keeps its reset selection.
  void apply_boot_rom_state();
  /// The register at `offset` (word aligned) as stored.
  uint32_t register_value(uint32_t offset) const;

 private:
  int find(uint32_t offset) const;
  uint32_t periph_clock_hz() const;
  void recompute();

  ChipContext& context_;
  CcmAnalog& analog_;
  std::array<uint32_t, 36> values_{};
  ClockRates last_rates_;
  std::vector<std::function<void(const ClockRates&)>> listeners_;
};

}  // namespace stepdance::sim::image::rt1062
