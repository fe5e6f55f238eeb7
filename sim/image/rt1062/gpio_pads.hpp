// The pads between the GPIO blocks, the IOMUXC, the GPRs and the world: who drives a pad, what
// its input reads, and the GPIO interrupt lines.
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/rt1062/gpio_port.hpp"
#include "image/rt1062/iomuxc.hpp"
#include "image/rt1062/iomuxc_gpr.hpp"
#include "image/rt1062/teensy_pins.hpp"

namespace stepdance::sim::image::rt1062 {

/// Owns GPIO1..9 and routes their pads (RM §12.1: GPIOn and its fast twin GPIOn+5 share the
/// pads; IOMUXC_GPR26..29 pick which one drives each pad, RM §11.4.27–30).
///
/// A Teensy pin whose pad's mux selects GPIO (ALT5) is the GPIO's: its configuration (output
/// when the selected block's GDIR bit is set, else input with the pad's pull: PKE+PUE with PUS 0
/// = pull-down, PUS 1..3 = pull-up, RM §11.7 SW_PAD_CTL) and its drive (DR) go to
/// BoardIo::pin_config/pin_drive at the time of the access that changed them, and the CPU's run
/// is stopped so the world sees the change then. A pin muxed to another function is left to
/// that function's model. A pad's input (PSR) reads BoardIo::pin_level when its input path is
/// on (ALT5, or SION), else 0; pads without a Teensy pin read their own drive (or their pull-up).
///
/// Interrupt lines (RM table 4-2 / §4.3): GPIO1 bits 0..7 also on GPIO1_INT0..7 (72..79);
/// GPIOn 0..15 / 16..31 on 80 + 2(n-1) / 81 + 2(n-1) for n = 1..5; GPIO6..9 together on 157.
class GpioPads : public GpioPadSide {
 public:
  GpioPads(ChipContext& context, BoardIo& world, TeensyModel model, Iomuxc& iomuxc, IomuxcGpr& gpr);

  /// GPIO`number` (1..9), to add to the bus.
  GpioPort& port(unsigned number) { return *ports_[number - 1]; }
  /// The world changed a pin's level (an outside device, a cable): takes every pad's level now,
  /// flagging edges for the interrupts. The image board calls this on the simulator thread.
  void world_changed();

  uint32_t pad_levels(unsigned number) override;
  void outputs_changed(unsigned number) override;
  void interrupts_changed() override;

 private:
  struct PinState {
    bool known = false;
    PinConfig config = PinConfig::kInput;
    bool high = false;
  };
  GpioPort& owner(int pad);
  bool pad_level(int pad);
  bool report_pin(uint8_t pin);
  void resample();

  ChipContext& context_;
  BoardIo& world_;
  TeensyModel model_;
  Iomuxc& iomuxc_;
  IomuxcGpr& gpr_;
  std::array<std::unique_ptr<GpioPort>, 9> ports_;
  std::array<int, 55> pin_pad_{};
  std::array<int, kPadCount> pad_pin_{};
  std::array<std::array<int, 32>, 4> port_pad_{};  ///< GPIO1..4 bit → pad, or -1
  std::array<PinState, 55> pins_{};
  std::array<bool, 160> irq_high_{};
};

}  // namespace stepdance::sim::image::rt1062
