// Digital pins of the HAL facade on the fast GPIO ports (RM §12) with IOMUXC pad settings (§11.7).
#if defined(__IMXRT1062__)

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/pins.hpp"

namespace stepdance::hal {

namespace teensy = platform::teensy;
namespace iomuxc = platform::teensy::regs::iomuxc;

namespace {

// Pad control for each mode: pulls are 22 kΩ up or 100 kΩ down, inputs get hysteresis.
uint32_t pad_for(PinMode mode) {
  switch (mode) {
    case PinMode::kInputPullup:
      return iomuxc::kPadKeeperEnable | iomuxc::kPadPullSelect | iomuxc::pad_pull(iomuxc::kPull22kUp) |
             iomuxc::kPadHysteresis;
    case PinMode::kInputPulldown:
      return iomuxc::kPadKeeperEnable | iomuxc::kPadPullSelect | iomuxc::pad_pull(iomuxc::kPull100kDown) |
             iomuxc::kPadHysteresis;
    case PinMode::kOutput: return teensy::kPadOutput;
    case PinMode::kInput: break;
  }
  return teensy::kPadInput;
}

}  // namespace

Status gpio_mode(uint8_t pin, PinMode mode) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  if (info == nullptr) return Status::kNoSuchPin;
  teensy::pad_configure(*info, pad_for(mode));
  teensy::pin_make_gpio(*info, mode == PinMode::kOutput);
  return Status::kOk;
}

bool gpio_read(uint8_t pin) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  return info != nullptr && teensy::pin_level(*info);
}

void gpio_write(uint8_t pin, bool high) {
  const teensy::PinInfo* info = teensy::pin_info(pin);
  if (info != nullptr) teensy::pin_drive(*info, high);
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
