// The SparkFun Qwiic Twist on I2C: its register file (SparkFun's register map) driven by a hand
// on the scenario's timeline (turn, press, release, click).
#pragma once

#include <array>
#include <cstdint>
#include <map>

#include "common/sim_time.hpp"
#include "models/i2c_bus.hpp"

namespace stepdance::sim {

/// Registers: 00h ID (5Ch), 01h status (bit 0 moved, 1 held, 2 clicked; a write replaces bits 0
/// and 2, held is read only),
/// 02h–03h version (1.2 here), 04h interrupt enables, 05h count (int16, little-endian),
/// 07h difference (int16), 09h/0Bh ms since the last movement / button event (uint16,
/// saturating), 0Dh–0Fh red/green/blue, 10h/12h/14h colour change per detent (int16),
/// 16h turn-interrupt timeout (uint16, ms), 18h new address. A transfer's first written byte
/// selects a register; following bytes, written or read, go on through the next registers.
/// The count moves one per detent (24 a turn); the moved bit and the difference follow it; a
/// press sets "held", a release clears it and sets "clicked". The INT output (low while an
/// enabled event is latched) is kept for observers: QWIIC cables carry no interrupt line.
class QwiicTwistModel : public I2cDevice {
 public:
  /// The knob's ID register holds `id` (5Ch on a real Twist; tests may plant another).
  explicit QwiicTwistModel(uint8_t id = 0x5C);

  bool write(SimTime time, const uint8_t* data, size_t length) override;
  void read(SimTime time, uint8_t* data, size_t length) override;

  /// `detents` turned evenly over `over` from `time` on (clockwise positive).
  void turn(SimTime time, int64_t detents, SimTime over);
  void press(SimTime time);
  void release(SimTime time);
  void click(SimTime time, SimTime hold);

  /// The register file as of the last transfer.
  uint8_t register_at(uint8_t address) const { return registers_[address]; }
  /// The count register as of `time` (applies the hand's events up to then).
  int16_t count_at(SimTime time);
  bool interrupt_active() const;
  uint64_t reads() const { return reads_; }
  uint64_t writes() const { return writes_; }

 private:
  enum class Event : uint8_t { kDetentForward, kDetentBack, kPress, kRelease };
  void advance_to(SimTime time);
  void apply(SimTime time, Event event);
  void set16(uint8_t address, uint16_t value);
  uint16_t get16(uint8_t address) const;
  void refresh_timers(SimTime time);

  std::array<uint8_t, 0x20> registers_{};
  uint8_t registers_pointer_ = 0;
  std::multimap<SimTime, Event> events_;
  SimTime last_movement_ = 0;
  SimTime last_button_ = 0;
  uint64_t reads_ = 0;
  uint64_t writes_ = 0;
};

}  // namespace stepdance::sim
