// analogRead of the CI firmware image: ADC1 (or ADC2 for the pins only it reaches), 10-bit results
// as Teensyduino's default, each the average of 4 samples. RM ADC chapter (ADC_CFG, ADC_GC, ADC_GS,
// ADC_HC0, ADC_HS, ADC_R0) and the external signal table of the ADC inputs.
//
// Both ADCs are calibrated at start-up (GC.CAL, then GS.CALF tells a failure), with the
// configuration they then convert with: 10-bit mode, long sample time, ADSTS = 2, the ADC's own
// asynchronous clock (ADICLK = 3, ADACK) divided by 2, high-speed mode, 4-sample hardware average.
#include <Arduino.h>
#include <stdint.h>

#include "stand_in_startup.h"
#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_adc.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"

volatile uint32_t stand_in_adc_calibration_failed = 0;

namespace {

namespace teensy = stepdance::platform::teensy;
namespace adc = teensy::regs::adc;
namespace ccm = teensy::regs::ccm;
namespace iomuxc = teensy::regs::iomuxc;

constexpr uint32_t kCfgHighSpeed = 1u << 10;  // ADC_CFG.ADHSC
constexpr uint32_t kCfg10Bit = adc::cfg_mode(1) | adc::cfg_sample_time(2) | adc::kCfgLongSample | adc::cfg_average(0) |
                               adc::cfg_divider(1) | adc::cfg_input_clock(3) | kCfgHighSpeed;
constexpr uint32_t kGcAverage4 = adc::kGcAverageEnable;  // AVGS = 0: 4 samples

struct Channel {
  uint8_t module;   // 0 = ADC1, 1 = ADC2
  uint8_t channel;  // ADCH, or kNone
};
constexpr uint8_t kNone = 0xFF;

// The ADC input of a pad (RM, ADC external signals): ADC1_IN0 = GPIO_AD_B1_11, IN1..4 =
// GPIO_AD_B0_12..15, IN5..15 = GPIO_AD_B1_00..10; ADC2_IN0 = GPIO_AD_B1_11, IN1..4 =
// GPIO_AD_B1_12..15, IN5..15 = GPIO_AD_B1_00..10. ADC1 is preferred where both reach a pad.
Channel channel_of(uint8_t pin) {
  const teensy::PinInfo pad = teensy::pin_pad(pin);
  if (pad.mux >= iomuxc::kMuxAdB100 && pad.mux < iomuxc::kMuxB000) {
    const uint8_t n = static_cast<uint8_t>((pad.mux - iomuxc::kMuxAdB100) / 4u);
    if (n <= 10) return {0, static_cast<uint8_t>(n + 5u)};
    if (n == 11) return {0, 0};
    return {1, static_cast<uint8_t>(n - 11u)};
  }
  if (pad.mux >= iomuxc::kMuxAdB000 + 4u * 12u && pad.mux < iomuxc::kMuxAdB100) {
    return {0, static_cast<uint8_t>((pad.mux - iomuxc::kMuxAdB000) / 4u - 11u)};
  }
  return {0, kNone};
}

bool calibrate(unsigned module) {
  adc::cfg(module) = kCfg10Bit;
  adc::gs(module) = adc::kGsCalibrationFailed;  // write 1 to clear an earlier failure
  adc::gc(module) = kGcAverage4 | adc::kGcCalibrate;
  while (adc::gc(module) & adc::kGcCalibrate) {
  }
  return (adc::gs(module) & adc::kGsCalibrationFailed) == 0;
}

}  // namespace

extern "C" STAND_IN_FLASH void stand_in_analog_start() {
  ccm::gate_on(ccm::kGateAdc1);
  ccm::gate_on(ccm::kGateAdc2);
  uint32_t failed = 0;
  if (!calibrate(0)) failed |= 1u;
  if (!calibrate(1)) failed |= 2u;
  stand_in_adc_calibration_failed = failed;
}

// Context: thread mode (it waits for the conversion, about 10 µs). Returns 0..1023, or 0 for a pin
// without an ADC input.
extern "C" int analogRead(uint8_t pin) {
  if (teensy::pin_info(pin) == nullptr) return 0;
  const Channel input = channel_of(pin);
  if (input.channel == kNone) return 0;
  adc::hc0(input.module) = adc::hc_channel(input.channel);  // starts one software-triggered conversion
  while ((adc::hs(input.module) & 1u) == 0) {               // HS.COCO0
  }
  return static_cast<int>(adc::r0(input.module) & 0x3FFu);  // reading R0 clears COCO0
}
