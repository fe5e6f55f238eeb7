// ADC1/ADC2: software-triggered single conversions for the analog round robin.
// RM, ADC chapter ("ADC memory map / register definition").
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::adc {

/// Base of ADC1 (module 0) or ADC2 (module 1). RM ADC memory map.
constexpr uint32_t base(unsigned module) { return 0x400C4000u + 0x4000u * module; }

/// HC0: control for conversion 0; writing it starts a software-triggered conversion. ADC_HC0.
inline Reg32 hc0(unsigned module) { return reg32(base(module) + 0x00u); }
constexpr uint32_t kHcInterruptEnable = 1u << 7;                   // AIEN
constexpr uint32_t hc_channel(uint32_t ch) { return ch & 0x1Fu; }  // ADCH
constexpr uint32_t kHcChannelOff = 0x1Fu;                          // ADCH = 31: conversion off
/// HS: conversion-complete flags (COCO0 bit 0). ADC_HS.
inline Reg32 hs(unsigned module) { return reg32(base(module) + 0x20u); }
/// R0: result of conversion 0; reading it clears COCO0. ADC_R0.
inline Reg32 r0(unsigned module) { return reg32(base(module) + 0x24u); }
/// CFG: configuration. ADC_CFG.
inline Reg32 cfg(unsigned module) { return reg32(base(module) + 0x44u); }
constexpr uint32_t cfg_input_clock(uint32_t adiclk) { return adiclk & 3u; }       // ADICLK: 1 = IPG/2
constexpr uint32_t cfg_mode(uint32_t mode) { return (mode & 3u) << 2; }           // MODE: 1 = 10-bit
constexpr uint32_t kCfgLongSample = 1u << 4;                                      // ADLSMP
constexpr uint32_t cfg_divider(uint32_t adiv) { return (adiv & 3u) << 5; }        // ADIV: 3 = /8
constexpr uint32_t cfg_sample_time(uint32_t adsts) { return (adsts & 3u) << 8; }  // ADSTS
constexpr uint32_t cfg_average(uint32_t avgs) { return (avgs & 3u) << 14; }       // AVGS: 3 = 32
constexpr uint32_t kCfgOverwrite = 1u << 16;                                      // OVWREN
/// GC: general control. ADC_GC.
inline Reg32 gc(unsigned module) { return reg32(base(module) + 0x48u); }
constexpr uint32_t kGcAverageEnable = 1u << 5;  // AVGE
constexpr uint32_t kGcCalibrate = 1u << 7;      // CAL, clears itself when calibration ends
/// GS: general status (CALF bit 1: calibration failed, write 1 to clear). ADC_GS.
inline Reg32 gs(unsigned module) { return reg32(base(module) + 0x4Cu); }
constexpr uint32_t kGsCalibrationFailed = 1u << 1;
constexpr uint32_t kGsConversionActive = 1u << 0;  // ADACT

}  // namespace stepdance::platform::teensy::regs::adc

#endif  // __IMXRT1062__
