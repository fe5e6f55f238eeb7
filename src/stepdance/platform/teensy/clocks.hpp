// Clock rates the backend derives its timer settings from (never hard-coded bus frequencies).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy {

/// IPG (bus) clock in Hz: the FlexPWM capture counters and the ENC filters run on it.
uint32_t bus_clock_hz();
/// PERCLK in Hz, read back from CCM_CSCMR1 (24 MHz crystal or IPG, divided): GPT2 runs on it.
uint32_t perclk_hz();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
