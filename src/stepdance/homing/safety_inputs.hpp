// SafetyInputs: hard limit switches, an emergency stop, and feed-hold / cycle-start buttons.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/homing/switch_debouncer.hpp"

namespace stepdance {

class Homing;
class TimeBasedInterpolator;

/// Digital safety inputs, each on any digital pin (the Driver Module's LIMIT_A…LIMIT_D, D1, D2,
/// A1…A4), sampled and debounced every millisecond in the kilohertz stage:
///  - a hard limit raises a fault (an alarm by default, or any level) when its switch closes,
///    except while a Homing routine owns that pin; after clearing the alarm the machine may be
///    jogged off the switch (only a new closing raises again);
///  - an emergency stop is fatal: outputs stop at once and the drivers are disabled;
///  - feed hold sets a planner's speed override to 0 (it slows to a stop within its
///    acceleration limit); cycle start restores the override it had.
/// Every switch closes to 3.3 V over the pin's pull-down (the original's wiring). It is normally
/// open (active high) unless added as normally closed (active low: the closed loop holds the pin
/// high, so a press or a broken wire reads as pressed).
/// Soft limits stay the channels' (Channel::set_upper_limit / set_lower_limit).
class SafetyInputs : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "SafetyInputs"; }
  /// Inputs one SafetyInputs can watch.
  static constexpr size_t kMaxInputs = 8;

  /// Adds a hard limit on `pin` that reports at `level` (default kAlarm). Context: loop.
  Status add_limit(uint8_t pin, bool normally_closed = false, FaultLevel level = FaultLevel::kAlarm);
  /// Adds an emergency stop (fatal; normally closed by default). Context: loop.
  Status add_emergency_stop(uint8_t pin, bool normally_closed = true);
  /// Adds a feed-hold / cycle-start button acting on `planner`. Context: loop.
  Status add_feed_hold(uint8_t pin, TimeBasedInterpolator* planner, bool normally_closed = false);
  Status add_cycle_start(uint8_t pin, TimeBasedInterpolator* planner, bool normally_closed = false);
  /// Limits on pins a running `homing` routine owns are ignored while it runs. Context: loop.
  void set_homing(Homing* homing) { homing_ = homing; }
  /// Milliseconds a level must hold to count (default 5). Context: loop.
  void set_debounce_ms(uint32_t ms);

  /// Configures the pins and registers the block in the kilohertz stage. Context: loop.
  Status begin();
  /// Samples every input and acts on the debounced changes. Context: kilohertz ISR.
  void run_kilohertz() override;
  /// limit_hits, emergency_stops, feed_holds, cycle_starts. Context: loop.
  void report_counters(CounterSink& sink) const override;

  /// Debounced level of input `index` (in add order): true = active. Context: any.
  bool active(size_t index) const { return index < count_ && inputs_[index].debouncer.level(); }
  uint32_t limit_hits() const { return limit_hits_; }

 private:
  enum class Role : uint8_t { kLimit, kEmergencyStop, kFeedHold, kCycleStart };
  struct Input {
    Role role = Role::kLimit;
    uint8_t pin = 255;
    bool normally_closed = false;
    FaultLevel level = FaultLevel::kAlarm;
    TimeBasedInterpolator* planner = nullptr;
    SwitchDebouncer debouncer;
  };

  Status add(Role role, uint8_t pin, bool normally_closed, FaultLevel level, TimeBasedInterpolator* planner);
  bool read(const Input& input) const;
  void on_activated(Input& input);

  Input inputs_[kMaxInputs];
  size_t count_ = 0;
  Homing* homing_ = nullptr;
  uint32_t debounce_ms_ = 5;
  float held_override_ = 1.0f;
  bool holding_ = false;
  uint32_t limit_hits_ = 0;
  uint32_t emergency_stops_ = 0;
  uint32_t feed_holds_ = 0;
  uint32_t cycle_starts_ = 0;
};

}  // namespace stepdance
