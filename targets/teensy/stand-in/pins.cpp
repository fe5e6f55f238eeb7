// pinMode, digitalRead and digitalWrite of the CI firmware image, on the fast GPIO6..9.
//
// A Teensy pin is a pad of the i.MX RT1062 (the table is the backend's, pins.hpp: pad mux register
// and GPIO bit). pinMode puts the pad in ALT5 = GPIO with SION (the input path stays on, so PSR
// reads the level of outputs too; RM §11.7 SW_MUX_CTL_PAD), sets its electrical configuration (RM
// §11.7 SW_PAD_CTL_PAD) and the direction bit (GPIO_GDIR, RM §12.5). The start-up already routed
// every pad to the fast GPIO6..9 (IOMUXC_GPR26..29 all ones, RM §11.4). Pins the board does not have
// are ignored (digitalRead returns LOW), as Teensyduino does.
#include <Arduino.h>
#include <stdint.h>

#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_core.hpp"
#include "stepdance/platform/teensy/regs_gpio.hpp"

namespace {

namespace teensy = stepdance::platform::teensy;
namespace iomuxc = teensy::regs::iomuxc;
namespace gpio = teensy::regs::gpio;
namespace ccm = teensy::regs::ccm;

// Gates of the pad multiplexer and of GPIO1..4, whose registers GPIO6..9 mirror (RM §14.7 CCGRn).
constexpr ccm::ClockGate kPinGates[] = {{4, 1}, {4, 2}, {1, 13}, {0, 15}, {2, 13}, {3, 6}};
bool gates_on = false;

// Pad settings per mode: the backend's (pins.hpp, gpio.cpp): pulls of 22 kΩ up or 100 kΩ down.
uint32_t pad_for(uint8_t mode) {
  switch (mode) {
    case OUTPUT: return teensy::kPadOutput;
    case INPUT_PULLUP:
      return iomuxc::kPadKeeperEnable | iomuxc::kPadPullSelect | iomuxc::pad_pull(iomuxc::kPull22kUp) |
             iomuxc::kPadHysteresis;
    case INPUT_PULLDOWN:
      return iomuxc::kPadKeeperEnable | iomuxc::kPadPullSelect | iomuxc::pad_pull(iomuxc::kPull100kDown) |
             iomuxc::kPadHysteresis;
    default: return teensy::kPadInput;
  }
}

}  // namespace

extern "C" {

// Context: thread mode or interrupt; GDIR is shared, so it is changed with interrupts masked.
void pinMode(uint8_t pin, uint8_t mode) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  if (info == nullptr) return;
  if (!gates_on) {
    for (const ccm::ClockGate& gate : kPinGates) ccm::gate_on(gate);
    gates_on = true;
  }
  iomuxc::pad_ctl(info->mux) = pad_for(mode);
  const uint32_t mask = 1u << info->bit;
  const uint32_t primask = teensy::regs::core::primask();
  teensy::regs::core::disable_irqs();
  if (mode == OUTPUT) {
    gpio::gdir(info->port) |= mask;
  } else {
    gpio::gdir(info->port) &= ~mask;
  }
  teensy::regs::core::set_primask(primask);
  iomuxc::pad_mux(info->mux) = iomuxc::kAltGpio | iomuxc::kMuxSion;
}

// Context: any. On an output, DR_SET/DR_CLEAR change only this pin's bit. On an input, as in
// Teensyduino (and Arduino's older convention), HIGH switches the pull-up on and LOW the pull-down.
void digitalWrite(uint8_t pin, uint8_t value) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  if (info == nullptr) return;
  const uint32_t mask = 1u << info->bit;
  if ((gpio::gdir(info->port) & mask) == 0) {
    iomuxc::pad_ctl(info->mux) = pad_for(value ? INPUT_PULLUP : INPUT_PULLDOWN);
  } else if (value) {
    gpio::dr_set(info->port) = mask;
  } else {
    gpio::dr_clear(info->port) = mask;
  }
}

// Context: any. The pad's level (GPIO_PSR).
uint8_t digitalRead(uint8_t pin) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  if (info == nullptr) return LOW;
  return (gpio::psr(info->port) >> info->bit) & 1u ? HIGH : LOW;
}

}  // extern "C"
