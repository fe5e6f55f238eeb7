// Clocks of the CI firmware image: the core at 600 MHz and the IPG (peripheral bus) at 150 MHz, as
// a Teensy 4 runs, plus the USB PLL. RM chapter 14 (CCM §14.7, CCM_ANALOG PLLs §14.8), the DCDC
// chapter (core supply) and the data sheet's operating points (600 MHz needs VDD_SOC 1.25 V).
//
// Clock tree used (RM Figure 14-2): 24 MHz oscillator → ARM PLL (PLL1) × 100 / 2 = 1200 MHz →
// ARM_PODF ÷2 = 600 MHz → PRE_PERIPH_CLK_SEL → periph_clk → AHB_PODF ÷1 = 600 MHz (core, AHB) →
// IPG_PODF ÷4 = 150 MHz (IPG). While PLL1 is reprogrammed the core runs from periph_clk2 = the
// oscillator. PERCLK (PIT, GPT) = oscillator ÷ 1 = 24 MHz.
//
// Clock gates (CCM_CCGR0..7): at reset almost all are on (RM §14.7.21-28: all ones but CCGR2
// CG11-12 and CCGR3 CG2), and none is switched off here; the stand-in switches on explicitly the gates of what
// it programs itself (DCDC here; ADC1/2 in analog.cpp, LPI2C1/3 in wire.cpp, IOMUXC and GPIO1..4
// in pins.cpp). The backend switches its own (regs_ccm.hpp).
#include <Arduino.h>
#include <stdint.h>

#include "stand_in_hooks.h"
#include "stand_in_registers.h"
#include "stand_in_startup.h"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_iomuxc.hpp"

volatile uint32_t F_CPU_ACTUAL = 600000000;  // set again by stand_in_clocks_start()
volatile uint32_t F_BUS_ACTUAL = 150000000;

namespace {

using stand_in::reg32;
namespace ccm = stand_in::ccm;
namespace analog = stand_in::analog;
namespace backend_ccm = stepdance::platform::teensy::regs::ccm;

constexpr uint32_t kOscillatorHz = 24000000;
constexpr uint32_t kArmPllMultiplier = 100;  // DIV_SELECT: 24 MHz × 100 / 2 = 1200 MHz
constexpr uint32_t kArmDivider = 2;          // ARM_PODF + 1
constexpr uint32_t kAhbDivider = 1;          // AHB_PODF + 1
constexpr uint32_t kIpgDivider = 4;          // IPG_PODF + 1
constexpr uint32_t kCoreHz = kOscillatorHz / 2 * kArmPllMultiplier / kArmDivider / kAhbDivider;
constexpr uint32_t kBusHz = kCoreHz / kIpgDivider;
static_assert(kCoreHz == 600000000 && kBusHz == 150000000, "F_CPU 600 MHz, F_BUS 150 MHz");

constexpr uint32_t kVddSoc600MHzMillivolts = 1250;
constexpr uint32_t kDcdcTarget = (kVddSoc600MHzMillivolts - 800) / 25;  // TRG = 18
constexpr backend_ccm::ClockGate kGateDcdc = {6, 3};                    // CCGR6 CG3

void wait_while(uint32_t address, uint32_t busy_bits) {
  while (reg32(address) & busy_bits) {
  }
}

void replace_field(uint32_t address, uint32_t mask, uint32_t value) {
  reg32(address) = (reg32(address) & ~mask) | value;
}

// Raises VDD_SOC before the frequency goes up (DCDC_REG3.TRG, then wait for DCDC_REG0.STS_DC_OK).
STAND_IN_FLASH void raise_core_voltage() {
  backend_ccm::gate_on(kGateDcdc);
  if ((reg32(stand_in::dcdc::kReg3) & stand_in::dcdc::kReg3TrgMask) >= kDcdcTarget) return;
  replace_field(stand_in::dcdc::kReg3, stand_in::dcdc::kReg3TrgMask, kDcdcTarget);
  while ((reg32(stand_in::dcdc::kReg0) & stand_in::dcdc::kReg0StsDcOk) == 0) {
  }
}

// Moves the core to periph_clk2 = the 24 MHz oscillator, so PLL1 can be changed under it.
STAND_IN_FLASH void run_from_oscillator() {
  replace_field(ccm::kCbcdr, ccm::kCbcdrPeriphClk2PodfMask, 0);
  replace_field(ccm::kCbcmr, ccm::kCbcmrPeriphClk2SelMask, ccm::kCbcmrPeriphClk2SelOsc);
  wait_while(ccm::kCdhipr, ccm::kCdhiprPeriph2ClkSelBusy);
  reg32(ccm::kCbcdr) |= ccm::kCbcdrPeriphClkSel;
  wait_while(ccm::kCdhipr, ccm::kCdhiprPeriphClkSelBusy);
}

// PLL1 to 1200 MHz: power down, then enable with the new loop divider and wait for LOCK.
STAND_IN_FLASH void start_arm_pll() {
  reg32(analog::kPllArm) = analog::kPllArmPowerDown;
  reg32(analog::kPllArm) = analog::kPllArmEnable | kArmPllMultiplier;
  while ((reg32(analog::kPllArm) & analog::kPllLock) == 0) {
  }
}

// Dividers for 600 / 600 / 150 MHz, then the core back onto PLL1 through pre_periph_clk.
STAND_IN_FLASH void run_from_arm_pll() {
  reg32(ccm::kCacrr) = kArmDivider - 1;
  wait_while(ccm::kCdhipr, ccm::kCdhiprArmPodfBusy);
  replace_field(ccm::kCbcdr, ccm::kCbcdrAhbPodfMask, (kAhbDivider - 1) << 10);
  wait_while(ccm::kCdhipr, ccm::kCdhiprAhbPodfBusy);
  replace_field(ccm::kCbcdr, ccm::kCbcdrIpgPodfMask, (kIpgDivider - 1) << 8);
  replace_field(ccm::kCbcmr, ccm::kCbcmrPrePeriphClkSelMask, ccm::kCbcmrPrePeriphArmPll);
  reg32(ccm::kCbcdr) &= ~ccm::kCbcdrPeriphClkSel;
  wait_while(ccm::kCdhipr, ccm::kCdhiprPeriphClkSelBusy);
}

}  // namespace

extern "C" STAND_IN_FLASH void stand_in_usb_pll_start() {
  const uint32_t pll = reg32(analog::kPllUsb1);
  if (pll & analog::kPllUsb1DivSelect) {  // 528 MHz mode: bypass, power down, then start afresh
    reg32(analog::kPllUsb1Set) = analog::kPllUsb1Bypass;
    reg32(analog::kPllUsb1Clr) = analog::kPllUsb1BypassClkSrcMask | analog::kPllUsb1Power | analog::kPllUsb1DivSelect |
                                 analog::kPllUsb1Enable | analog::kPllUsb1EnUsbClks;
  }
  reg32(analog::kPllUsb1Set) = analog::kPllUsb1Enable | analog::kPllUsb1Power;
  while ((reg32(analog::kPllUsb1) & analog::kPllLock) == 0) {
  }
  reg32(analog::kPllUsb1Clr) = analog::kPllUsb1Bypass;
  reg32(analog::kPllUsb1Set) = analog::kPllUsb1EnUsbClks;
}

extern "C" STAND_IN_FLASH void stand_in_clocks_start() {
  namespace iomuxc = stepdance::platform::teensy::regs::iomuxc;
  // PERCLK (PIT, GPT) from the oscillator, undivided: 24 MHz whatever the core runs at.
  backend_ccm::cscmr1() =
      (backend_ccm::cscmr1() & ~backend_ccm::kCscmr1PerclkPodfMask) | backend_ccm::kCscmr1PerclkSelOsc;
  // Every pad's GPIO goes to the fast GPIO6..9 (IOMUXC_GPR26..29, RM §11.4), as on a Teensy.
  for (unsigned port = 0; port < 4; ++port) iomuxc::gpr_fast_gpio_select(port) = 0xFFFFFFFFu;
  stand_in_usb_pll_start();
  raise_core_voltage();
  run_from_oscillator();
  start_arm_pll();
  run_from_arm_pll();
  F_CPU_ACTUAL = kCoreHz;
  F_BUS_ACTUAL = kBusHz;
}
