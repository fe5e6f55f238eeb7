// One call that builds the RT1062's clock, pin and time blocks and adds them to the bus.
#pragma once

#include <array>
#include <memory>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/adc.hpp"
#include "image/rt1062/analog_window.hpp"
#include "image/rt1062/ccm.hpp"
#include "image/rt1062/ccm_analog.hpp"
#include "image/rt1062/dcdc.hpp"
#include "image/rt1062/flexspi.hpp"
#include "image/rt1062/gpio_pads.hpp"
#include "image/rt1062/gpt.hpp"
#include "image/rt1062/iomuxc.hpp"
#include "image/rt1062/iomuxc_gpr.hpp"
#include "image/rt1062/ocotp.hpp"
#include "image/rt1062/pit.hpp"
#include "image/rt1062/quad_timer.hpp"
#include "image/rt1062/snvs.hpp"
#include "image/rt1062/teensy_pins.hpp"
#include "image/rt1062/tempmon.hpp"

namespace stepdance::sim::image::rt1062 {

/// The blocks, owned together; they must outlive the bus's use of them. Members are public so
/// the image board can wire them (ccm.add_rates_listener → the CPU's core clock,
/// gpio.world_changed() when the world moves a pin, gpr for FlexRAM).
struct ClockAndPinBlocks {
  ClockAndPinBlocks(ChipContext& context, BoardIo& world, TeensyModel model);

  /// Optional, before the image runs: the clocks as the boot ROM leaves them instead of the
  /// manual's reset values — PLL1 (ARM) locked at 792 MHz ÷ ARM_PODF 2 (its reset value) =
  /// 396 MHz core, IPG ÷3 = 132 MHz, PLL2 locked at 528 MHz. Inferred, not from ROM
  /// documentation: Teensyduino's clockspeed.c starts F_CPU_ACTUAL at 396 MHz and F_BUS_ACTUAL at
  /// 132 MHz, and its set_arm_clock never writes PRE_PERIPH_CLK_SEL, so the ROM must leave the
  /// reset selection (PLL1 ÷ ARM_PODF) for the 600 MHz it sets to reach the core. Without this
  /// call the core starts at the manual's reset state: 12 MHz.
  void apply_boot_rom_clocks() {
    ccm_analog.apply_boot_rom_state();
    ccm.apply_boot_rom_state();
  }

  CcmAnalog ccm_analog;
  Pmu pmu;
  Ocotp ocotp;
  Tempmon tempmon;
  AnalogWindow analog_window;  ///< 0x400D8000: CCM_ANALOG, PMU, TEMPMON; add USB_ANALOG here
  Ccm ccm;
  Dcdc dcdc;
  Iomuxc iomuxc;
  IomuxcGpr gpr;
  GpioPads gpio;
  Gpt gpt1;
  Gpt gpt2;
  Pit pit;
  Adc adc1;
  Adc adc2;
  Snvs snvs;
  std::array<QuadTimer, 4> quad_timers{QuadTimer(1), QuadTimer(2), QuadTimer(3), QuadTimer(4)};
  FlexSpi flexspi1{1};
  FlexSpi flexspi2{2};
};

/// Creates the clock, pin and time blocks for a Teensy `model`, adds each to `bus`, and makes
/// the CCM the bus's gate query. Returns them (the caller keeps them alive), or null, with the
/// bus untouched, if any of them would overlap a block already on the bus. Call once, before
/// the image runs, on the simulator thread.
std::unique_ptr<ClockAndPinBlocks> add_clock_and_pin_blocks(PeripheralBus& bus, ChipContext& context, BoardIo& world,
                                                            TeensyModel model);

}  // namespace stepdance::sim::image::rt1062
