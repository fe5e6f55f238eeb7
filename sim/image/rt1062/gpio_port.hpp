// One GPIO block (RM chapter 12, registers §12.5): GPIO1..5 on the peripheral bus and the fast
// GPIO6..9 on the AHB, each 32 pins with data, direction, pad status and interrupt registers.
#pragma once

#include <cstdint>

#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::rt1062 {

/// What a GPIO block needs from the pads around it (GpioPads implements it).
class GpioPadSide {
 public:
  virtual ~GpioPadSide() = default;
  /// The levels on the pads of port `number` (1..9) now, bit n = pin n (what PSR reads).
  virtual uint32_t pad_levels(unsigned number) = 0;
  /// DR or GDIR of port `number` changed: the pads it drives may change.
  virtual void outputs_changed(unsigned number) = 0;
  /// ISR or IMR of a port changed: the interrupt lines may change.
  virtual void interrupts_changed() = 0;
};

/// GPIO`number` (1..9). DR, GDIR, ICR1/2, IMR, EDGE_SEL are read/write, PSR reads the pads, ISR
/// is write-1-to-clear, DR_SET/CLEAR/TOGGLE write DR (RM §12.5.1–12.5.11). Interrupt detection
/// (RM §12.4.3.1): ICR 00 low level, 01 high level, 10 rising, 11 falling; EDGE_SEL overrides
/// with either edge. ISR bits latch whether or not IMR enables them.
class GpioPort : public Peripheral {
 public:
  GpioPort(unsigned number, GpioPadSide& side);

  const char* name() const override { return kNames[number_]; }
  uint32_t base() const override;
  uint32_t size_bytes() const override { return 0x4000u; }
  ClockGate gate() const override;
  Access read(uint32_t offset, uint8_t bytes, uint32_t& value) override;
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override;

  unsigned number() const { return number_; }
  uint32_t dr() const { return dr_; }
  uint32_t gdir() const { return gdir_; }
  /// Interrupts flagged and enabled (ISR & IMR).
  uint32_t pending() const { return isr_ & imr_; }
  /// Takes the pads' levels now: flags edges since the last sample and levels held.
  void sample(uint32_t levels);

 private:
  static constexpr const char* kNames[10] = {"",      "GPIO1", "GPIO2", "GPIO3", "GPIO4",
                                             "GPIO5", "GPIO6", "GPIO7", "GPIO8", "GPIO9"};
  uint32_t detect(uint32_t before, uint32_t after) const;
  bool write_word(uint32_t word, uint32_t value);

  unsigned number_;
  GpioPadSide& side_;
  uint32_t dr_ = 0, gdir_ = 0, icr1_ = 0, icr2_ = 0, imr_ = 0, isr_ = 0, edge_sel_ = 0;
  uint32_t last_levels_ = 0;
  bool sampled_ = false;
};

}  // namespace stepdance::sim::image::rt1062
