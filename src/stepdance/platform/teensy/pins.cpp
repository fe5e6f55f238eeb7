// Pad multiplexing and fast-GPIO access for Teensy pins (RM §11.7 IOMUXC, §11.4 GPR, §12 GPIO).
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/pins.hpp"

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/regs_gpio.hpp"

namespace stepdance::platform::teensy {

namespace iomuxc = regs::iomuxc;
namespace gpio = regs::gpio;

void pad_select(const PinInfo& pin, uint32_t alt) { iomuxc::pad_mux(pin.mux) = alt; }

void pad_configure(const PinInfo& pin, uint32_t pad_ctl) { iomuxc::pad_ctl(pin.mux) = pad_ctl; }

void pin_make_gpio(const PinInfo& pin, bool output) {
  const uint32_t mask = 1u << pin.bit;
  // GPR26..29 and GDIR are shared by many pins: read-modify-write them with interrupts off.
  hal::CriticalSection guard;
  iomuxc::gpr_fast_gpio_select(pin.port) |= mask;
  if (output) {
    gpio::gdir(pin.port) |= mask;
  } else {
    gpio::gdir(pin.port) &= ~mask;
  }
  // SION keeps the input path on, so PSR reads the real pin level of outputs as well.
  pad_select(pin, iomuxc::kAltGpio | iomuxc::kMuxSion);
}

void pin_drive(const PinInfo& pin, bool high) {
  const uint32_t mask = 1u << pin.bit;
  if (high) {
    gpio::dr_set(pin.port) = mask;
  } else {
    gpio::dr_clear(pin.port) = mask;
  }
}

bool pin_level(const PinInfo& pin) { return (gpio::psr(pin.port) >> pin.bit) & 1u; }

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
