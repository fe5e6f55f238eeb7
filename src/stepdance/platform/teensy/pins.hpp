// Teensy 4.x pin numbers → i.MX RT1062 pads and fast-GPIO bits, plus small pad/GPIO helpers.
// Pad names and GPIO bits are facts from the Teensy 4.0/4.1 schematics; pad register offsets from
// RM §11.7 (IOMUXC) and GPIO port/bit correspondence from RM §12 (GPIO) and §11.4 (GPR26..29).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/boards/teensy_pinout.hpp"
#include "stepdance/platform/teensy/regs_iomuxc.hpp"

#if defined(ARDUINO_TEENSY_MICROMOD)
#error "Stepdance supports the Teensy 4.0 and 4.1 only (its boards use their pinouts)."
#endif

namespace stepdance::platform::teensy {

/// One Teensy pin: its pad (by SW_MUX_CTL offset) and its bit in a fast GPIO port.
struct PinInfo {
  uint16_t mux;  ///< offset of SW_MUX_CTL_PAD_GPIO_<pad> from the IOMUXC base
  uint8_t port;  ///< fast GPIO port index: 0..3 = GPIO6..GPIO9
  uint8_t bit;   ///< bit in that port (and in the matching GPR26..29 select register)
};

namespace pad {
// Pad banks and their GPIO routing (RM §11.7 pad order; GPIO1..4 ≙ fast GPIO6..9).
constexpr PinInfo ad_b0(uint8_t n) { return {static_cast<uint16_t>(regs::iomuxc::kMuxAdB000 + 4u * n), 0, n}; }
constexpr PinInfo ad_b1(uint8_t n) {
  return {static_cast<uint16_t>(regs::iomuxc::kMuxAdB100 + 4u * n), 0, static_cast<uint8_t>(16u + n)};
}
constexpr PinInfo b0(uint8_t n) { return {static_cast<uint16_t>(regs::iomuxc::kMuxB000 + 4u * n), 1, n}; }
constexpr PinInfo b1(uint8_t n) {
  return {static_cast<uint16_t>(regs::iomuxc::kMuxB100 + 4u * n), 1, static_cast<uint8_t>(16u + n)};
}
constexpr PinInfo sd_b0(uint8_t n) {
  return {static_cast<uint16_t>(regs::iomuxc::kMuxSdB000 + 4u * n), 2, static_cast<uint8_t>(12u + n)};
}
// EMC_00..31 are GPIO4 (GPIO9) bits 0..31; EMC_32..41 are GPIO3 (GPIO8) bits 18..27.
constexpr PinInfo emc(uint8_t n) {
  return n < 32 ? PinInfo{static_cast<uint16_t>(regs::iomuxc::kMuxEmc00 + 4u * n), 3, n}
                : PinInfo{static_cast<uint16_t>(regs::iomuxc::kMuxEmc00 + 4u * n), 2, static_cast<uint8_t>(n - 14u)};
}
}  // namespace pad

/// Pins 0..33 are the same on the Teensy 4.0 and 4.1.
constexpr PinInfo kCommonPins[34] = {
    pad::ad_b0(3),  pad::ad_b0(2),  pad::emc(4),    pad::emc(5),   pad::emc(6),     // 0-4
    pad::emc(8),    pad::b0(10),    pad::b1(1),     pad::b1(0),    pad::b0(11),     // 5-9
    pad::b0(0),     pad::b0(2),     pad::b0(1),     pad::b0(3),    pad::ad_b1(2),   // 10-14
    pad::ad_b1(3),  pad::ad_b1(7),  pad::ad_b1(6),  pad::ad_b1(1), pad::ad_b1(0),   // 15-19
    pad::ad_b1(10), pad::ad_b1(11), pad::ad_b1(8),  pad::ad_b1(9), pad::ad_b0(12),  // 20-24
    pad::ad_b0(13), pad::ad_b1(14), pad::ad_b1(15), pad::emc(32),  pad::emc(31),    // 25-29
    pad::emc(37),   pad::emc(36),   pad::b0(12),    pad::emc(7),                    // 30-33
};

#if defined(ARDUINO_TEENSY40)
/// Teensy 4.0 pins 34..39: the SD-card pads on the underside.
constexpr PinInfo kBoardPins[6] = {pad::sd_b0(3), pad::sd_b0(2), pad::sd_b0(1),
                                   pad::sd_b0(0), pad::sd_b0(5), pad::sd_b0(4)};
/// The Teensy this build is for (its pin facts: boards/teensy_pinout.hpp).
inline constexpr const TeensyPinout& kThisTeensy = kTeensy40;
#else
/// Teensy 4.1 pins 34..41.
constexpr PinInfo kBoardPins[8] = {pad::b1(13),    pad::b1(12),    pad::b1(2),    pad::b1(3),
                                   pad::ad_b1(12), pad::ad_b1(13), pad::ad_b1(4), pad::ad_b1(5)};
inline constexpr const TeensyPinout& kThisTeensy = kTeensy41;
#endif

/// Highest pin number this backend knows on the selected Teensy.
constexpr uint8_t kMaxPin = static_cast<uint8_t>(34u + sizeof(kBoardPins) / sizeof(kBoardPins[0]) - 1u);
static_assert(kMaxPin <= kThisTeensy.highest_pin, "the pad table lists a pin the Teensy does not have");

/// The pad and GPIO bit of a Teensy pin (constant expression), or {0, 0, 0} if there is none.
constexpr PinInfo pin_pad(uint8_t pin) {
  return pin < 34 ? kCommonPins[pin] : pin <= kMaxPin ? kBoardPins[pin - 34u] : PinInfo{0, 0, 0};
}

/// The FlexIO3 pin a Teensy pin's pad carries in ALT9 (AD_B1_nn → nn, B1_nn → 16 + nn), or 0xFF
/// if its pad has no FlexIO3 function. RM §11.7 (pad ALT9 = FLEXIO3_FLEXIOnn).
constexpr uint8_t flexio3_pin(uint8_t pin) {
  const PinInfo pad = pin_pad(pin);
  const bool ad_b1 = pad.mux >= regs::iomuxc::kMuxAdB100 && pad.mux < regs::iomuxc::kMuxB000;
  const bool b1 = pad.mux >= regs::iomuxc::kMuxB100 && pad.mux < regs::iomuxc::kMuxSdB000;
  return ad_b1 ? static_cast<uint8_t>(pad.bit - 16u) : b1 ? pad.bit : uint8_t{0xFF};
}

/// The pad and GPIO bit of a Teensy pin, or nullptr if the board has no such pin.
inline const PinInfo* pin_info(uint8_t pin) {
  if (pin < 34) return &kCommonPins[pin];
  if (pin <= kMaxPin) return &kBoardPins[pin - 34u];
  return nullptr;
}

/// Selects a pad's alternate function (ALT0..9), optionally with SION. RM §11.7.
void pad_select(const PinInfo& pin, uint32_t alt);
/// Sets a pad's electrical configuration (pulls, keeper, drive, hysteresis). RM §11.7.
void pad_configure(const PinInfo& pin, uint32_t pad_ctl);
/// Makes a pin a fast-GPIO pin (GPR select, GPIO mux) driven as `output` or read as input.
void pin_make_gpio(const PinInfo& pin, bool output);
/// Drives a GPIO output pin. Context: any.
void pin_drive(const PinInfo& pin, bool high);
/// Level on a pin (valid for inputs and, thanks to SION, for outputs). Context: any.
bool pin_level(const PinInfo& pin);

/// Pad settings we use: plain input with hysteresis, push-pull output, analog (everything off).
constexpr uint32_t kPadInput = regs::iomuxc::kPadHysteresis;
constexpr uint32_t kPadOutput = regs::iomuxc::pad_drive(6) | regs::iomuxc::pad_speed(1);
constexpr uint32_t kPadAnalog = 0;

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
