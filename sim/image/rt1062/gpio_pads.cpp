// Pads between GPIO1..9, the IOMUXC, the GPRs and the world.
#include "image/rt1062/gpio_pads.hpp"

#include "image/rt1062/pads.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// SW_PAD_CTL fields (RM §11.7): PKE bit 12, PUE bit 13 (1 = pull, 0 = keeper), PUS bits 15:14.
constexpr uint32_t kPke = 1u << 12, kPue = 1u << 13;
constexpr unsigned kPusShift = 14;

constexpr unsigned kIrqGpio1Int0 = 72, kIrqGpio1Low = 80, kIrqGpio6789 = 157;

PinConfig input_config(uint32_t pad_ctl) {
  if ((pad_ctl & (kPke | kPue)) != (kPke | kPue)) return PinConfig::kInput;
  return ((pad_ctl >> kPusShift) & 3u) == 0 ? PinConfig::kInputPulldown : PinConfig::kInputPullup;
}

}  // namespace

GpioPads::GpioPads(ChipContext& context, BoardIo& world, TeensyModel model, Iomuxc& iomuxc, IomuxcGpr& gpr)
    : context_(context), world_(world), model_(model), iomuxc_(iomuxc), gpr_(gpr) {
  for (unsigned n = 1; n <= 9; ++n) ports_[n - 1] = std::make_unique<GpioPort>(n, *this);
  pad_pin_.fill(-1);
  for (unsigned n = 1; n <= 4; ++n) {
    for (unsigned bit = 0; bit < 32; ++bit) port_pad_[n - 1][bit] = gpio_pad(n, bit);
  }
  pin_pad_.fill(-1);
  for (uint8_t pin = 0; pin <= highest_pin(model_); ++pin) {
    pin_pad_[pin] = teensy_pin_pad(model_, pin);
    if (pin_pad_[pin] >= 0) pad_pin_[static_cast<size_t>(pin_pad_[pin])] = pin;
  }
  // At reset every pin is a GPIO input with the keeper (SW_PAD_CTL 0x10B0): the world's default.
  for (PinState& state : pins_) state.known = true;
  iomuxc_.add_pad_listener([this](int) { outputs_changed(0); });
  gpr_.add_change_listener([this](unsigned index) {
    if (index >= 26 && index <= 29) outputs_changed(0);
  });
}

// The block driving a pad: GPIOn, or GPIOn+5 where GPR25+n selects the fast twin.
GpioPort& GpioPads::owner(int pad) {
  const GpioBit gpio = pad_gpio(pad);
  const bool fast = gpr_.fast_gpio_selected(gpio.port, gpio.bit);
  return port(fast ? gpio.port + 5u : gpio.port);
}

bool GpioPads::pad_level(int pad) {
  const uint32_t mux = iomuxc_.pad_mux(pad);
  if ((mux & 0xFu) != Iomuxc::kMuxAltGpio && !(mux & Iomuxc::kMuxSion)) return false;
  const int pin = pad_pin_[static_cast<size_t>(pad)];
  if (pin >= 0) return world_.pin_level(context_.now_ns(), static_cast<uint8_t>(pin));
  const GpioPort& driver = owner(pad);
  const uint32_t mask = 1u << pad_gpio(pad).bit;
  if (iomuxc_.pad_is_gpio(pad) && (driver.gdir() & mask)) return (driver.dr() & mask) != 0;
  return input_config(iomuxc_.pad_ctl(pad)) == PinConfig::kInputPullup;
}

uint32_t GpioPads::pad_levels(unsigned number) {
  if (number == 5) return 0;  // GPIO5 is on the SNVS pads: no Teensy pin, not modelled as inputs
  const auto& pads = port_pad_[(number > 5 ? number - 5u : number) - 1u];
  uint32_t levels = 0;
  for (unsigned bit = 0; bit < 32; ++bit) {
    const int pad = pads[bit];
    if (pad >= 0 && pad_level(pad)) levels |= 1u << bit;
  }
  return levels;
}

// Tells the world about `pin`'s configuration and drive if they changed; true if it did.
bool GpioPads::report_pin(uint8_t pin) {
  const int pad = pin_pad_[pin];
  if (pad < 0 || !iomuxc_.pad_is_gpio(pad)) return false;
  const GpioPort& driver = owner(pad);
  const uint32_t mask = 1u << pad_gpio(pad).bit;
  const bool output = (driver.gdir() & mask) != 0;
  const PinConfig config = output ? PinConfig::kOutput : input_config(iomuxc_.pad_ctl(pad));
  const bool high = (driver.dr() & mask) != 0;
  PinState& state = pins_[pin];
  bool changed = false;
  if (config != state.config) {
    world_.pin_config(context_.now_ns(), pin, config);
    changed = true;
  }
  if (output && (high != state.high || config != state.config)) {
    world_.pin_drive(context_.now_ns(), pin, high);
    changed = true;
  }
  state.config = config;
  if (output) state.high = high;
  return changed;
}

void GpioPads::outputs_changed(unsigned) {
  bool changed = false;
  for (uint8_t pin = 0; pin <= highest_pin(model_); ++pin) changed = report_pin(pin) || changed;
  if (!changed) return;
  context_.stop_cpu_run();
  resample();
}

void GpioPads::resample() {
  for (auto& p : ports_) p->sample(pad_levels(p->number()));
  interrupts_changed();
}

void GpioPads::world_changed() { resample(); }

void GpioPads::interrupts_changed() {
  std::array<bool, 160> high{};
  for (unsigned n = 1; n <= 5; ++n) {
    const uint32_t pending = port(n).pending();
    high[kIrqGpio1Low + 2u * (n - 1u)] = (pending & 0xFFFFu) != 0;
    high[kIrqGpio1Low + 2u * (n - 1u) + 1u] = (pending >> 16) != 0;
  }
  for (unsigned bit = 0; bit < 8; ++bit) high[kIrqGpio1Int0 + bit] = (port(1).pending() >> bit) & 1u;
  for (unsigned n = 6; n <= 9; ++n) high[kIrqGpio6789] = high[kIrqGpio6789] || port(n).pending() != 0;
  for (unsigned irq = kIrqGpio1Int0; irq < high.size(); ++irq) {
    if (high[irq] == irq_high_[irq]) continue;
    irq_high_[irq] = high[irq];
    context_.set_irq_level(irq, high[irq]);
  }
}

}  // namespace stepdance::sim::image::rt1062
