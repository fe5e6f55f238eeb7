// The clock roots the motion blocks count with, read from the CCM registers through the bus.
#pragma once

#include <cstdint>

#include "image/chip/peripheral_bus.hpp"

namespace stepdance::sim::image {

/// FLEXIO2_CLK_ROOT (which also clocks FlexIO3), in Hz: CCM_CSCMR2 FLEXIO2_CLK_SEL selects the
/// source (only 3 = PLL3 is modelled: 480 MHz, or 528 MHz with CCM_ANALOG_PLL_USB1 DIV_SELECT),
/// divided by CCM_CS1CDR FLEXIO2_CLK_PRED + 1 and FLEXIO2_CLK_PODF + 1 (RM §14.4 figure 14-2,
/// §14.7.8 CSCMR2, §14.7.10 CS1CDR, §14.8.2 PLL_USB1). False if a register cannot be read or the
/// source is not modelled. Context: a register access or event.
bool flexio2_root_hz(const PeripheralBus& bus, uint32_t& hz);

/// IPG_CLK_ROOT in Hz: the AHB clock (the core clock) divided by CCM_CBCDR IPG_PODF + 1
/// (RM §14.4, §14.7.5 CBCDR). False if CBCDR cannot be read. Context: a register access or event.
bool ipg_root_hz(const PeripheralBus& bus, uint32_t core_hz, uint32_t& hz);

/// LPI2C_CLK_ROOT in Hz: CCM_CSCDR2 LPI2C_CLK_SEL (bit 18: 1 = the 24 MHz oscillator, 0 = PLL3
/// / 8 = 60 MHz) divided by LPI2C_CLK_PODF + 1 (bits 24:19) (RM §14.4, §14.7.13 CSCDR2). False if
/// CSCDR2 cannot be read. Context: a register access or event.
bool lpi2c_root_hz(const PeripheralBus& bus, uint32_t& hz);

}  // namespace stepdance::sim::image
