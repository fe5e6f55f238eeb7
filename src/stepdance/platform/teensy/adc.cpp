// Analog inputs: ADC1 and ADC2 each convert their begun pins round-robin, in the background.
//
// Every conversion-complete interrupt stores the 10-bit result of one pin, bumps that pin's sample
// counter and starts the next pin of the same ADC. 32-sample hardware averaging, long sample time,
// ADC clock = IPG / 2 / 8 (about 9.4 MHz at a 150 MHz bus): roughly 6 kHz of conversions per ADC,
// shared by its pins. RM, ADC chapter (memory map / register definition).
#if defined(__IMXRT1062__)

#include <stddef.h>

#include "stepdance/boards/board.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/irq.hpp"
#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_adc.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_nvic.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace adc = regs::adc;
namespace ccm = regs::ccm;

/// A Teensy pin with an ADC input: module (0 = ADC1, 1 = ADC2) and channel (reference §4.6).
struct AnalogWiring {
  uint8_t pin;
  uint8_t module;
  uint8_t channel;
};

constexpr AnalogWiring kAnalogPins[] = {
    {14, 1, 7}, {15, 1, 8},  {16, 0, 12}, {17, 0, 11}, {18, 0, 6}, {19, 1, 5}, {20, 0, 15},
    {21, 1, 0}, {22, 0, 13}, {23, 1, 14}, {24, 0, 1},  {25, 0, 2}, {26, 1, 3}, {27, 1, 4},
#if !defined(ARDUINO_TEENSY40)
    {38, 1, 1}, {39, 1, 2},  {40, 0, 9},  {41, 0, 10},
#endif
};
constexpr size_t kMaxPinsPerModule = sizeof(kAnalogPins) / sizeof(kAnalogPins[0]);

constexpr bool has_adc_channel(uint8_t pin) {
  for (const AnalogWiring& wiring : kAnalogPins) {
    if (wiring.pin == pin) return true;
  }
  return false;
}
// The channel table covers exactly the analog pins of this Teensy (boards/teensy_pinout.hpp).
constexpr bool channels_match_teensy() {
  if (kMaxPinsPerModule != kThisTeensy.analog_pin_count) return false;
  for (uint8_t i = 0; i < kThisTeensy.analog_pin_count; ++i) {
    if (!has_adc_channel(kThisTeensy.analog_pins[i])) return false;
  }
  return true;
}
static_assert(channels_match_teensy(), "the ADC channel table and the Teensy's analog pins differ");
// Every analog pin of every board on this Teensy (A1..A4, the drivers' VREF read-back) has a channel.
constexpr bool analog_pins_have_channels(const BoardDefinition& board) {
  for (uint8_t pin : board.io_a) {
    if (pin != kNoPin && !has_adc_channel(pin)) return false;
  }
  for (uint8_t port = 0; port < board.output_port_count; ++port) {
    const uint8_t vref = board.output_ports[port].vref;
    if (vref != kNoPin && !has_adc_channel(vref)) return false;
  }
  return true;
}
constexpr bool boards_have_channels() {
  for (const BoardDefinition* board : kBoards) {
    if (board_takes(*board, kThisTeensy) && !analog_pins_have_channels(*board)) return false;
  }
  return true;
}
static_assert(boards_have_channels(), "an analog pin of a board has no ADC channel");

/// One ADC's round robin: the pins it converts, in begin() order.
struct RoundRobin {
  uint8_t pins[kMaxPinsPerModule] = {};
  uint8_t channels[kMaxPinsPerModule] = {};
  volatile uint8_t count = 0;
  uint8_t current = 0;
  bool running = false;
};

RoundRobin modules[2];
bool calibration_done[2] = {};  // our calibration, with our settings, has succeeded on this module
volatile uint16_t values[kMaxPin + 1] = {};
volatile uint32_t sample_counts[kMaxPin + 1] = {};
bool begun[kMaxPin + 1] = {};

const AnalogWiring* find(uint8_t pin) {
  for (const AnalogWiring& wiring : kAnalogPins) {
    if (wiring.pin == pin) return &wiring;
  }
  return nullptr;
}

void start_conversion(uint8_t module, uint8_t channel) {
  adc::hc0(module) = adc::kHcInterruptEnable | adc::hc_channel(channel);
}

void service(uint8_t module) {
  RoundRobin& robin = modules[module];
  const uint32_t raw = adc::r0(module);  // clears the conversion-complete flag
  const uint8_t pin = robin.pins[robin.current];
  values[pin] = static_cast<uint16_t>(raw & 0x3FFu);
  sample_counts[pin] = sample_counts[pin] + 1;
  robin.current = static_cast<uint8_t>(robin.current + 1u < robin.count ? robin.current + 1u : 0u);
  start_conversion(module, robin.channels[robin.current]);
}

void adc1_isr() { service(0); }
void adc2_isr() { service(1); }

// Busy-waits until `bits` of `reg` are clear, at most 100 ms. Context: loop.
bool wait_clear(regs::Reg32 reg, uint32_t bits) {
  const uint32_t started = hal::micros_now();
  while (reg & bits) {
    if (hal::micros_now() - started > 100000u) return false;
  }
  return true;
}

// Configures and calibrates an ADC once (busy-waits a few ms for the calibration). Safe on top of
// Teensyduino's boot calibration and any analogRead(): a calibration still running is waited for,
// a conversion in progress is stopped, and only then do CFG and GC change (RM ADC chapter:
// calibrate with the final clock and sample settings, with no conversion running).
Status calibrate(uint8_t module) {
  if (calibration_done[module]) return Status::kOk;
  ccm::gate_on(module == 0 ? ccm::kGateAdc1 : ccm::kGateAdc2);
  if (!wait_clear(adc::gc(module), adc::kGcCalibrate)) return Status::kUnsupported;
  adc::hc0(module) = adc::kHcChannelOff;
  if (!wait_clear(adc::gs(module), adc::kGsConversionActive)) return Status::kUnsupported;
  adc::cfg(module) = adc::cfg_input_clock(1) | adc::cfg_divider(3) | adc::cfg_mode(1) | adc::kCfgLongSample |
                     adc::cfg_sample_time(3) | adc::cfg_average(3) | adc::kCfgOverwrite;
  adc::gs(module) = adc::kGsCalibrationFailed;
  adc::gc(module) = adc::kGcAverageEnable | adc::kGcCalibrate;
  if (!wait_clear(adc::gc(module), adc::kGcCalibrate)) return Status::kUnsupported;
  if (adc::gs(module) & adc::kGsCalibrationFailed) return Status::kUnsupported;
  calibration_done[module] = true;
  return Status::kOk;
}

Status start_module(uint8_t module) {
  const Status calibrated = calibrate(module);
  if (calibrated != Status::kOk) {
    hal::log_message("adc_begin: ADC calibration failed");
    return calibrated;
  }
  RoundRobin& robin = modules[module];
  robin.current = 0;
  irq::install(module == 0 ? regs::nvic::kIrqAdc1 : regs::nvic::kIrqAdc2, module == 0 ? &adc1_isr : &adc2_isr,
               irq::kAdcPriority);
  robin.running = true;
  start_conversion(module, robin.channels[0]);
  return Status::kOk;
}

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status adc_begin(uint8_t pin) {
  const teensy::AnalogWiring* wiring = teensy::find(pin);
  if (wiring == nullptr || pin > teensy::kMaxPin) return Status::kNoSuchPin;
  if (teensy::begun[pin]) return Status::kOk;
  const teensy::PinInfo& info = *teensy::pin_info(pin);
  teensy::pad_configure(info, teensy::kPadAnalog);  // keeper and pulls off: they bias the input
  teensy::pin_make_gpio(info, false);
  teensy::RoundRobin& robin = teensy::modules[wiring->module];
  {
    CriticalSection guard;  // the ADC ISR walks this list
    robin.pins[robin.count] = pin;
    robin.channels[robin.count] = wiring->channel;
    robin.count = static_cast<uint8_t>(robin.count + 1u);
  }
  teensy::begun[pin] = true;
  if (robin.running) return Status::kOk;
  const Status started = teensy::start_module(wiring->module);
  if (started != Status::kOk) {
    CriticalSection guard;
    robin.count = static_cast<uint8_t>(robin.count - 1u);
    teensy::begun[pin] = false;
  }
  return started;
}

uint16_t adc_read(uint8_t pin) { return pin <= teensy::kMaxPin ? teensy::values[pin] : 0; }

uint32_t adc_sample_count(uint8_t pin) { return pin <= teensy::kMaxPin ? teensy::sample_counts[pin] : 0; }

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
